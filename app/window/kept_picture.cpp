#include "window/kept_picture.h"

namespace rm {

GLuint KeptPicture::target(glm::ivec2 size) {
  if (size != size_ || !fbo_) {
    color_ = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(color_.get(), 1, GL_RGBA8, size.x, size.y);
    fbo_ = gl::make_framebuffer();
    glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, color_.get(), 0);
    size_ = size;
    drawn_ = false;
  }
  return fbo_.get();
}

void KeptPicture::present() const {
  if (!fbo_) return;
  glBlitNamedFramebuffer(fbo_.get(), 0, 0, 0, size_.x, size_.y, 0, 0, size_.x, size_.y, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
}

}  // namespace rm
