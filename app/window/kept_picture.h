// The picture the graph drew last, kept in a texture of the window's size, so
// that the interface can be drawn again over it (a hover, a HUD line) without
// running the shader again: a scene that does not change is not re-rendered.
#pragma once
#include <glm/glm.hpp>

#include "core/gl.h"

namespace rm {

class KeptPicture {
 public:
  // The framebuffer the graph draws the picture into, at `size` (reallocated
  // when the size changes, which also forgets the picture).
  GLuint target(glm::ivec2 size);
  bool has_picture() const { return drawn_; }
  void mark_drawn() { drawn_ = true; }
  void forget() { drawn_ = false; }  // the picture moved on without it
  // Copies the picture to the window's framebuffer (0), at the same size.
  void present() const;

 private:
  glm::ivec2 size_{0};
  bool drawn_ = false;
  gl::Texture color_;
  gl::Framebuffer fbo_;
};

}  // namespace rm
