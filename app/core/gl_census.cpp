#include "core/gl_census.h"

#include <algorithm>

#include "core/gl.h"

namespace rm {

namespace {

// Drivers hand out names either counting up or reusing the lowest free one.
// A freshly made object's name shows how far the names reach now; every name
// seen so far is remembered too, so the scan covers both schemes.
struct Kind {
  GLboolean (*is)(GLuint);
  GLuint (*make)();
  void (*free)(GLuint);
  GLuint highest_seen = 0;
};

int count(Kind& kind) {
  const GLuint probe = kind.make();
  kind.free(probe);
  kind.highest_seen = std::max(kind.highest_seen, probe);
  const GLuint end = kind.highest_seen * 2 + 256;  // reused names sit below
  int live = 0;
  for (GLuint n = 1; n < end; ++n) {
    if (!kind.is(n)) continue;
    ++live;
    kind.highest_seen = std::max(kind.highest_seen, n);
  }
  return live;
}

}  // namespace

int GlCensus::total() const {
  return programs + shaders + textures + buffers + framebuffers + renderbuffers + vertex_arrays + queries;
}

GlCensus take_gl_census() {
  // Shaders and programs share one name space in GL; the rest have their own.
  static Kind programs{[](GLuint n) { return glIsProgram(n); }, [] { return glCreateProgram(); },
                       [](GLuint n) { glDeleteProgram(n); }};
  static Kind shaders{[](GLuint n) { return glIsShader(n); }, [] { return glCreateShader(GL_FRAGMENT_SHADER); },
                      [](GLuint n) { glDeleteShader(n); }};
  static Kind textures{[](GLuint n) { return glIsTexture(n); },
                       [] { GLuint n = 0; glCreateTextures(GL_TEXTURE_2D, 1, &n); return n; },
                       [](GLuint n) { glDeleteTextures(1, &n); }};
  static Kind buffers{[](GLuint n) { return glIsBuffer(n); }, [] { GLuint n = 0; glCreateBuffers(1, &n); return n; },
                      [](GLuint n) { glDeleteBuffers(1, &n); }};
  static Kind framebuffers{[](GLuint n) { return glIsFramebuffer(n); },
                           [] { GLuint n = 0; glCreateFramebuffers(1, &n); return n; },
                           [](GLuint n) { glDeleteFramebuffers(1, &n); }};
  static Kind renderbuffers{[](GLuint n) { return glIsRenderbuffer(n); },
                            [] { GLuint n = 0; glCreateRenderbuffers(1, &n); return n; },
                            [](GLuint n) { glDeleteRenderbuffers(1, &n); }};
  static Kind vertex_arrays{[](GLuint n) { return glIsVertexArray(n); },
                            [] { GLuint n = 0; glCreateVertexArrays(1, &n); return n; },
                            [](GLuint n) { glDeleteVertexArrays(1, &n); }};
  static Kind queries{[](GLuint n) { return glIsQuery(n); },
                      [] { GLuint n = 0; glCreateQueries(GL_TIME_ELAPSED, 1, &n); return n; },
                      [](GLuint n) { glDeleteQueries(1, &n); }};
  GlCensus census;
  census.programs = count(programs);
  census.shaders = count(shaders);
  census.textures = count(textures);
  census.buffers = count(buffers);
  census.framebuffers = count(framebuffers);
  census.renderbuffers = count(renderbuffers);
  census.vertex_arrays = count(vertex_arrays);
  census.queries = count(queries);
  return census;
}

std::string to_string(const GlCensus& c) {
  return "programs " + std::to_string(c.programs) + ", shaders " + std::to_string(c.shaders) + ", textures " +
         std::to_string(c.textures) + ", buffers " + std::to_string(c.buffers) + ", framebuffers " +
         std::to_string(c.framebuffers) + ", renderbuffers " + std::to_string(c.renderbuffers) +
         ", vertex arrays " + std::to_string(c.vertex_arrays) + ", queries " + std::to_string(c.queries);
}

}  // namespace rm
