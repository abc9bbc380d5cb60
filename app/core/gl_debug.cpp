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
  // A shader's compile errors come back from Program::build with their file
  // and line (and a twin the driver rejects is only not there): the driver's
  // raw copy would repeat them.
  glDebugMessageControl(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_FALSE);
  glDebugMessageCallback(
      [](GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar* message, const void*) {
        ++errors;
        std::cerr << "raymarching: GL error: " << message << '\n';
      },
      nullptr);
}

}  // namespace rm
