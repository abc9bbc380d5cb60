#include "core/driver_ready.h"

#include <cstdint>

#include "core/address_space.h"
#include "core/gl.h"

namespace rm {

std::optional<std::string> driver_cannot_draw() {
  // Far longer than a 1x1 clear takes on any machine, however busy (not
  // timed on its own: a 16x9 render took as long with it as before it);
  // waited out only on the way to an error.
  constexpr std::uint64_t kWaitNs = 5'000'000'000;
  GLint previous = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  GLuint pixel = 0, framebuffer = 0;
  glGenRenderbuffers(1, &pixel);
  glBindRenderbuffer(GL_RENDERBUFFER, pixel);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, pixel);
  glClear(GL_COLOR_BUFFER_BIT);
  GLsync cleared = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  const GLenum waited = glClientWaitSync(cleared, GL_SYNC_FLUSH_COMMANDS_BIT, kWaitNs);
  if (waited == GL_TIMEOUT_EXPIRED || waited == GL_WAIT_FAILED) {
    // The objects stay: deleting them could wait on the same draw.
    return "the OpenGL driver cannot finish a draw" + within_address_space_limit() +
           ": Mesa's llvmpipe could not start all its drawing threads (out of memory or of threads)";
  }
  glDeleteSync(cleared);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous));
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(1, &pixel);
  return std::nullopt;
}

}  // namespace rm
