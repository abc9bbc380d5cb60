// The picture the graph drew last, kept in a float texture, so that the
// interface can be drawn again over it (a hover, a HUD line) without running
// the shader again: a scene that does not change is not re-rendered. The
// picture may be smaller than the window (the frame budget's scale), may be
// drawn in tiles over several presents (until a tile is drawn, the previous
// picture shows there), and at rest gathers supersamples: float keeps their
// running mean exact, so a screenshot of it equals `render --samples`.
#pragma once
#include <optional>

#include <glm/glm.hpp>

#include "core/image.h"
#include "core/renderer.h"

namespace rm {

// What the window shows where there is no picture yet.
constexpr float kNoPictureGrey[4] = {0.1f, 0.1f, 0.1f, 1.0f};

class KeptPicture {
 public:
  // The framebuffer the graph draws the picture into, at `size`. A new size
  // starts with the previous picture stretched over it.
  GLuint target(glm::ivec2 size);
  bool has_picture() const { return drawn_; }
  void mark_drawn() { drawn_ = true; }
  glm::ivec2 size() const { return kept_ ? glm::ivec2(kept_->width(), kept_->height()) : glm::ivec2(0); }
  // Copies the picture over the window's framebuffer (0) of `window` pixels,
  // stretched (bilinear) when it is smaller.
  void present(glm::ivec2 window) const;
  Image read() const { return kept_->read(); }  // top row first

 private:
  bool drawn_ = false;
  std::optional<RenderTarget> kept_;
};

}  // namespace rm
