// The shader's own uniforms: what it declares that the host does not supply
// (core/host_inputs.h), each with the control its declaration asks for in a
// comment on the same line, and the values a frame gives them.
//
//   uniform float speed;   // ui: min=0 max=4 step=0.1 default=1
//   uniform vec3 tint;     // ui: color default=1,0.5,0.2
//   uniform bool rings;    // ui: default=true
//
// Types with a control: float, int, bool, vec2, vec3, vec4. An array, or a
// comment after `ui:` that cannot be read, is a warning, never a failure.
// `render --set NAME=VALUE` gives a value; a screenshot records every value.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/inputs.h"
#include "core/source.h"

namespace rm {

struct UserUniform {
  enum class Type { Float, Int, Bool, Vec2, Vec3, Vec4 };
  std::string name;
  Type type = Type::Float;
  int components = 1;
  float min = 0.0f, max = 1.0f, step = 0.0f;  // step 0: continuous
  std::vector<float> initial;                 // `default=`, or zeros
  bool color = false;                         // a vec3 or vec4 shown as a colour
  std::string path;                           // where it is declared
  int line = 0;
};

struct UserUniforms {
  std::vector<UserUniform> uniforms;  // in declaration order, each name once
  Diagnostics warnings;
  const UserUniform* find(const std::string& name) const;
};

// The uniforms the source declares in its active code (not in an `#if`
// branch the preprocessor drops), less the host's inputs and channels.
// `active` is glslang's preprocessed source.text, line for line (validate()
// makes it); without it, the preprocessor is run here when needed.
UserUniforms find_user_uniforms(const Source& source, const std::string* active = nullptr);

// A value as `--set` and the screenshot metadata spell it: "1.5", "3",
// "true", "0.1,0.2,0.3". nullopt with *error if it does not fit `u`.
std::optional<std::vector<float>> parse_uniform_value(const UserUniform& u, const std::string& text,
                                                      std::string* error);
std::string uniform_value_text(const UserUniform::Type type, const std::vector<float>& value);

// Every uniform at its `default=`, then each "NAME=VALUE" of `sets` (as
// `render --set` takes them) in its place. nullopt with *error on a NAME the
// shader does not declare or a VALUE that does not fit ("'NAME=VALUE': why").
std::optional<std::vector<UniformValue>> uniform_values(const UserUniforms& uniforms,
                                                        const std::vector<std::string>& sets, std::string* error);

// The uniforms of several passes as one list: a name declared in more than
// one pass is one uniform (the first declaration's control).
void merge_user_uniforms(UserUniforms* into, const UserUniforms& more);

}  // namespace rm
