// Small RAII owners for GL object names. Each frees its name when destroyed;
// they move but never copy. All need the GL context current.
#pragma once
#include <epoxy/gl.h>

#include <utility>

namespace rm::gl {

inline void delete_shader(GLuint n) { glDeleteShader(n); }
inline void delete_program(GLuint n) { glDeleteProgram(n); }
inline void delete_texture(GLuint n) { glDeleteTextures(1, &n); }
inline void delete_framebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void delete_vertex_array(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void delete_query(GLuint n) { glDeleteQueries(1, &n); }
inline void delete_sampler(GLuint n) { glDeleteSamplers(1, &n); }

template <void (*Delete)(GLuint)>
class Object {
 public:
  Object() = default;
  explicit Object(GLuint name) : name_(name) {}
  Object(Object&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  ~Object() { reset(); }

  GLuint get() const { return name_; }
  explicit operator bool() const { return name_ != 0; }
  void reset() {
    if (name_) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

using Shader = Object<delete_shader>;
using Program = Object<delete_program>;
using Texture = Object<delete_texture>;
using Framebuffer = Object<delete_framebuffer>;
using VertexArray = Object<delete_vertex_array>;
using Query = Object<delete_query>;
using Sampler = Object<delete_sampler>;

inline Texture make_texture(GLenum target) {
  GLuint n = 0;
  glCreateTextures(target, 1, &n);
  return Texture(n);
}
inline Framebuffer make_framebuffer() {
  GLuint n = 0;
  glCreateFramebuffers(1, &n);
  return Framebuffer(n);
}
inline Sampler make_sampler() {
  GLuint n = 0;
  glCreateSamplers(1, &n);
  return Sampler(n);
}
inline Query make_query(GLenum target) {
  GLuint n = 0;
  glCreateQueries(target, 1, &n);
  return Query(n);
}
inline VertexArray make_vertex_array() {
  GLuint n = 0;
  glCreateVertexArrays(1, &n);
  return VertexArray(n);
}

}  // namespace rm::gl
