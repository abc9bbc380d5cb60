// Program: the driver's compile and link of a validated Source, plus a table
// of the uniforms the linked program actually reads.
#pragma once
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/diagnostics.h"
#include "core/gl.h"
#include "core/source.h"

namespace rm {

struct UniformInfo {
  GLint location = -1;
  GLenum type = 0;
  GLint size = 1;                 // array length
  std::vector<GLint> elements;    // location of each array element
  bool sampler = false;           // a sampler of any shape (its value is a texture unit)
};

class Program {
 public:
  // Compiles and links; on failure returns nullopt and fills *diags with
  // the driver's messages mapped to the user's files.
  static std::optional<Program> build(const Source& source, Diagnostics* diags);

  GLuint id() const { return program_.get(); }
  bool uses(const std::string& name) const { return uniforms_.count(name) != 0; }
  const std::unordered_map<std::string, UniformInfo>& uniforms() const { return uniforms_; }

  // Sets a float/int/bool uniform of 1-4 components from floats, converting to
  // the declared type; names the program does not use are ignored, so
  // complete shaders receive only the inputs they declare.
  void set(const std::string& name, const float* values, int components) const;
  void set(const std::string& name, float v) const { set(name, &v, 1); }
  // Sets element [index] of an array uniform.
  void set_element(const std::string& name, int index, const float* values, int components) const;
  void set_sampler(const std::string& name, int unit) const;
  // Sets a float array uniform from its first element on (as many as it has).
  void set_floats(const std::string& name, const std::vector<float>& values) const;

 private:
  gl::Program program_;
  std::unordered_map<std::string, UniformInfo> uniforms_;
};

}  // namespace rm
