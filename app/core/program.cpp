#include "core/program.h"

#include <algorithm>
#include <cstring>

#include "core/address_space.h"
#include "core/check.h"
#include "core/dialect_names.h"

namespace rm {

namespace {

// A triangle that covers the viewport; the fragment shader does all the work.
std::string vertex_source(const std::string& version_line) {
  return version_line + R"(
void main() {
  vec2 corner = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1));
  gl_Position = vec4(corner - 1.0, 0.0, 1.0);
}
)";
}

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  if (is_program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  return log;
}

gl::Shader compile(GLenum stage, const std::string& text, std::string* log) {
  gl::Shader shader(glCreateShader(stage));
  const char* ptr = text.c_str();
  glShaderSource(shader.get(), 1, &ptr, nullptr);
  glCompileShader(shader.get());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    *log = info_log(shader.get(), false);
    shader.reset();
  }
  return shader;
}

int components_of(GLenum type) {
  switch (type) {
    case GL_FLOAT_VEC2: case GL_INT_VEC2: case GL_UNSIGNED_INT_VEC2: case GL_BOOL_VEC2: return 2;
    case GL_FLOAT_VEC3: case GL_INT_VEC3: case GL_UNSIGNED_INT_VEC3: case GL_BOOL_VEC3: return 3;
    case GL_FLOAT_VEC4: case GL_INT_VEC4: case GL_UNSIGNED_INT_VEC4: case GL_BOOL_VEC4: return 4;
    default: return 1;
  }
}

bool is_sampler(GLenum type) {
  switch (type) {
    case GL_SAMPLER_1D: case GL_SAMPLER_2D: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_1D_SHADOW: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_1D_ARRAY: case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_1D_ARRAY_SHADOW: case GL_SAMPLER_2D_ARRAY_SHADOW: case GL_SAMPLER_2D_MULTISAMPLE:
    case GL_SAMPLER_2D_MULTISAMPLE_ARRAY: case GL_SAMPLER_CUBE_SHADOW: case GL_SAMPLER_BUFFER:
    case GL_SAMPLER_2D_RECT: case GL_SAMPLER_2D_RECT_SHADOW: case GL_SAMPLER_CUBE_MAP_ARRAY:
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
    case GL_INT_SAMPLER_1D: case GL_INT_SAMPLER_2D: case GL_INT_SAMPLER_3D: case GL_INT_SAMPLER_CUBE:
    case GL_INT_SAMPLER_1D_ARRAY: case GL_INT_SAMPLER_2D_ARRAY: case GL_INT_SAMPLER_2D_MULTISAMPLE:
    case GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY: case GL_INT_SAMPLER_BUFFER: case GL_INT_SAMPLER_2D_RECT:
    case GL_INT_SAMPLER_CUBE_MAP_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_1D: case GL_UNSIGNED_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_CUBE: case GL_UNSIGNED_INT_SAMPLER_1D_ARRAY: case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE: case GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_BUFFER: case GL_UNSIGNED_INT_SAMPLER_2D_RECT:
    case GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY:
      return true;
    default:
      return false;
  }
}

bool is_float(GLenum type) {
  return type == GL_FLOAT || type == GL_FLOAT_VEC2 || type == GL_FLOAT_VEC3 || type == GL_FLOAT_VEC4;
}

void upload(GLuint program, GLint location, GLenum type, const float* values, int given) {
  const int n = components_of(type);
  float f[4] = {0, 0, 0, 0};
  for (int i = 0; i < std::min(n, given); ++i) f[i] = values[i];
  if (is_float(type)) {
    switch (n) {
      case 1: glProgramUniform1fv(program, location, 1, f); break;
      case 2: glProgramUniform2fv(program, location, 1, f); break;
      case 3: glProgramUniform3fv(program, location, 1, f); break;
      default: glProgramUniform4fv(program, location, 1, f); break;
    }
    return;
  }
  if (type == GL_FLOAT_MAT2 || type == GL_FLOAT_MAT3 || type == GL_FLOAT_MAT4) return;
  GLint iv[4];
  for (int i = 0; i < 4; ++i) iv[i] = static_cast<GLint>(f[i]);
  switch (n) {
    case 1: glProgramUniform1iv(program, location, 1, iv); break;
    case 2: glProgramUniform2iv(program, location, 1, iv); break;
    case 3: glProgramUniform3iv(program, location, 1, iv); break;
    default: glProgramUniform4iv(program, location, 1, iv); break;
  }
}

}  // namespace

std::optional<Program> Program::build(const Source& source, Diagnostics* diags) {
  require_room_for_driver();  // Mesa would crash where it runs out
  std::string log;
  gl::Shader fragment = compile(GL_FRAGMENT_SHADER, source.text, &log);
  if (!fragment) {
    *diags = map_log(log, source, LogFormat::Mesa);
    if (count_errors(*diags) == 0) diags->push_back({Severity::Error, source.scene_path(), 0, 0, "the driver rejected the shader"});
    return std::nullopt;
  }
  gl::Shader vertex = compile(GL_VERTEX_SHADER, vertex_source(source.version_line), &log);
  if (!vertex) {
    diags->push_back({Severity::Error, source.scene_path(), 0, 0,
                      "the host's vertex shader failed for '" + source.version_line + "': " + log});
    return std::nullopt;
  }
  Program p;
  p.program_ = gl::Program(glCreateProgram());
  glAttachShader(p.id(), vertex.get());
  glAttachShader(p.id(), fragment.get());
  glLinkProgram(p.id());
  glDetachShader(p.id(), vertex.get());
  glDetachShader(p.id(), fragment.get());
  GLint ok = GL_FALSE;
  glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    *diags = map_log(info_log(p.id(), true), source, LogFormat::Mesa);
    if (count_errors(*diags) == 0) diags->push_back({Severity::Error, source.scene_path(), 0, 0, "the driver could not link the shader"});
    return std::nullopt;
  }

  GLint count = 0;
  glGetProgramiv(p.id(), GL_ACTIVE_UNIFORMS, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256];
    GLsizei length = 0;
    UniformInfo info;
    glGetActiveUniform(p.id(), static_cast<GLuint>(i), sizeof name, &length, &info.size, &info.type, name);
    std::string key(name, static_cast<size_t>(length));
    if (auto bracket = key.find('['); bracket != std::string::npos) key.resize(bracket);
    info.location = glGetUniformLocation(p.id(), name);
    info.sampler = is_sampler(info.type);
    for (GLint e = 0; e < info.size; ++e)
      info.elements.push_back(glGetUniformLocation(p.id(), (key + "[" + std::to_string(e) + "]").c_str()));
    // Set by the name the code gives it: `uniform float smooth;` is rm_smooth to the driver.
    if (info.location >= 0) p.uniforms_[with_names_restored(key, source.renamed)] = std::move(info);
  }
  return p;
}

void Program::set(const std::string& name, const float* values, int components) const {
  auto it = uniforms_.find(name);
  if (it == uniforms_.end()) return;
  upload(id(), it->second.location, it->second.type, values, components);
}

void Program::set_element(const std::string& name, int index, const float* values, int components) const {
  auto it = uniforms_.find(name);
  if (it == uniforms_.end() || index < 0 || index >= it->second.size) return;
  const GLint location = it->second.elements[static_cast<size_t>(index)];
  if (location >= 0) upload(id(), location, it->second.type, values, components);
}

void Program::set_floats(const std::string& name, const std::vector<float>& values) const {
  auto it = uniforms_.find(name);
  if (it == uniforms_.end() || it->second.type != GL_FLOAT) return;
  const GLsizei count = std::min(static_cast<GLsizei>(values.size()), static_cast<GLsizei>(it->second.size));
  if (count > 0) glProgramUniform1fv(id(), it->second.location, count, values.data());
}

void Program::set_sampler(const std::string& name, int unit) const {
  auto it = uniforms_.find(name);
  if (it != uniforms_.end()) glProgramUniform1i(id(), it->second.location, unit);
}

}  // namespace rm
