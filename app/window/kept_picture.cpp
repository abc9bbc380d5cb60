#include "window/kept_picture.h"

namespace rm {

GLuint KeptPicture::target(glm::ivec2 size) {
  if (size != this->size()) {
    RenderTarget fresh(size.x, size.y);
    if (!drawn_) glClearNamedFramebufferfv(fresh.framebuffer(), GL_COLOR, 0, kNoPictureGrey);
    else glBlitNamedFramebuffer(kept_->framebuffer(), fresh.framebuffer(), 0, 0, kept_->width(), kept_->height(), 0, 0,
                                size.x, size.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    kept_.emplace(std::move(fresh));
  }
  return kept_->framebuffer();
}

void KeptPicture::present(glm::ivec2 window) const {
  if (!kept_) return;
  const glm::ivec2 size = this->size();
  glBlitNamedFramebuffer(kept_->framebuffer(), 0, 0, 0, size.x, size.y, 0, 0, window.x, window.y, GL_COLOR_BUFFER_BIT,
                         size == window ? GL_NEAREST : GL_LINEAR);
}

}  // namespace rm
