#include "window/kept_picture.h"

namespace rm {

GLuint KeptPicture::target(glm::ivec2 size) {
  if (size != size_ || !fbo_) {
    gl::Texture color = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(color.get(), 1, GL_RGBA8, size.x, size.y);
    gl::Framebuffer fbo = gl::make_framebuffer();
    glNamedFramebufferTexture(fbo.get(), GL_COLOR_ATTACHMENT0, color.get(), 0);
    if (!drawn_) glClearNamedFramebufferfv(fbo.get(), GL_COLOR, 0, kNoPictureGrey);
    else glBlitNamedFramebuffer(fbo_.get(), fbo.get(), 0, 0, size_.x, size_.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT,
                             GL_LINEAR);
    color_ = std::move(color);
    fbo_ = std::move(fbo);
    size_ = size;
  }
  return fbo_.get();
}

void KeptPicture::present(glm::ivec2 window) const {
  if (!fbo_) return;
  glBlitNamedFramebuffer(fbo_.get(), 0, 0, 0, size_.x, size_.y, 0, 0, window.x, window.y, GL_COLOR_BUFFER_BIT,
                         size_ == window ? GL_NEAREST : GL_LINEAR);
}

}  // namespace rm
