#include "core/gl_debug.h"

#include <atomic>
#include <iostream>

#include "core/gl.h"

namespace rm {

namespace {
std::atomic<int> errors{0};
}  // namespace

int gl_errors_reported() { return errors.load(); }

void report_gl_errors() {
  glEnable(GL_DEBUG_OUTPUT);
  // Only errors: performance and portability notes would drown them.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  glDebugMessageCallback(
      [](GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar* message, const void*) {
        ++errors;
        std::cerr << "raymarching: GL error: " << message << '\n';
      },
      nullptr);
}

}  // namespace rm
