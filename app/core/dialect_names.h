// Names a shader's own dialect leaves free that GLSL 4.50 core reserves.
//
// The host compiles a Shadertoy shader (written for GLSL ES 3.00, WebGL 2)
// and a glslViewer one (GLSL 1.10, ES 1.00) as `#version 450 core`, where
// words such as `buffer` and `sample` are keywords, and `texture` is a
// function: `vec4 buffer = texture(iChannel0, uv);` runs on Shadertoy and
// was a syntax error here, and glslViewer's `uniform sampler2D texture;`
// hid the function that `texture2D` calls.
// Each such word that the code uses as a name is renamed for the compiler by
// a host `#define buffer rm_buffer`, and its messages name it back.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace rm {

enum class Dialect {
  EsSl300,  // Shadertoy: GLSL ES 3.00
  Glsl110,  // glslViewer, Book of Shaders: GLSL 1.10 or 1.20, or ES 1.00
};

// The words of `dialect` free as names, reserved in 4.50 core, that `code`
// (its comments stripped) uses as names and only so: never as the word
// 4.50 makes of them (`precise float`, `layout(`, `flat in`, a call of
// `texture(`), and never defined as a macro of its own.
std::vector<std::string> names_core_reserves(std::string_view code, Dialect dialect);

// What the compiler sees for `word`: rm_<word>.
std::string compiler_name(std::string_view word);

// `message` with each of `words`' compiler names spelt as the code spells it.
std::string with_names_restored(std::string_view message, const std::vector<std::string>& words);

}  // namespace rm
