// Renderer: draws one frame of a program with given inputs, on screen or into
// an offscreen float target, and reads pictures back.
#pragma once
#include <algorithm>
#include <vector>

#include <glm/glm.hpp>

#include "core/channels.h"
#include "core/gl.h"
#include "core/image.h"
#include "core/inputs.h"
#include "core/program.h"

namespace rm {

// An offscreen RGBA32F framebuffer, so EXR output keeps unclamped floats.
class RenderTarget {
 public:
  RenderTarget(int width, int height);
  void bind() const;
  Image read() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  gl::Texture color_;
  gl::Framebuffer fbo_;
};

// What can change a program's picture, read from its active uniforms: a
// shader that reads no clock draws the same picture until an input it reads
// changes, so the window need not draw it again.
struct InputUse {
  bool time = false;     // iTime, iTimeDelta, iFrame, iFrameRate, iDate, iChannelTime, u_time, u_delta, u_frame, u_date
  bool drag = false;     // iMouse: changes while the left button is held, and on press and release
  bool pointer = false;  // u_mouse: follows the pointer, button or not
};
InputUse inputs_read(const Program& program);

class Renderer {
 public:
  Renderer();  // needs a current GL context
  // Sets every input the program reads and draws over the bound framebuffer's
  // (0,0,size) viewport.
  void draw(const Program& program, const FrameInputs& inputs, const Channels& channels, glm::ivec2 size) const;

  // Renders offscreen at `size`, in tiles no larger than the driver allows;
  // tiling shifts fragCoord, which only the Shadertoy wrapper honours, so
  // callers check supports_tiles() first.
  Image render_image(const Program& program, FrameInputs inputs, const Channels& channels, glm::ivec2 size) const;
  int max_tile() const { return max_tile_; }
  void limit_tile(int pixels) { max_tile_ = std::max(1, std::min(max_tile_, pixels)); }  // tests tiling

 private:
  gl::VertexArray vao_;
  int max_tile_ = 4096;
};

}  // namespace rm
