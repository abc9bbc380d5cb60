// Renderer: draws one frame of a program with given inputs, on screen or into
// an offscreen float target, and reads pictures back.
#pragma once
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/gl.h"
#include "core/image.h"
#include "core/host_inputs.h"
#include "core/program.h"
#include "core/supersampling.h"

namespace rm {

// An offscreen RGBA32F framebuffer, so EXR output keeps unclamped floats.
class RenderTarget {
 public:
  static constexpr GLenum kFormat = GL_RGBA32F;
  // Throws std::bad_alloc when the driver has no memory for it (16 bytes a
  // pixel): whoever asked for the picture says so in one line, and nothing
  // draws into a target that is not there.
  RenderTarget(int width, int height);
  void bind() const;
  GLuint framebuffer() const { return fbo_.get(); }
  GLuint texture() const { return color_.get(); }
  Image read() const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_;
  gl::Texture color_;
  gl::Framebuffer fbo_;
};

// What one iChannel shows a pass when it draws.
struct ChannelInput {
  GLenum target = GL_TEXTURE_2D;
  GLuint texture = 0;  // 0: nothing bound (the graph binds a transparent black texel instead)
  GLuint sampler = 0;  // filter and wrap; 0: the texture's own
  glm::vec3 resolution{0.0f};
  std::string sampler_name;  // the spec's: a sampler of the shader's own it binds too
};
using ChannelInputs = std::array<ChannelInput, 4>;

// The context state every pass is drawn with: Shadertoy filters across cube
// faces (WebGL 2 always does). Set once per context.
void set_sampling_state();

// Binds each channel's texture and sampler to its unit and points the
// program's iChannelN (and u_texN, and its sampler_name) at it. Any other
// sampler the shader declares reads kNothingBoundUnit, where no texture is:
// black, not iChannel0 by default.
constexpr int kNothingBoundUnit = 4;
void bind_channels(const Program& program, const ChannelInputs& channels);

// Draws one pixel of `program` into a throwaway target of `format`, reading
// `channels`, in the current context. A driver that generates a program's
// machine code at its first draw, for the target's format and the textures'
// formats and samplers (llvmpipe), does that work here, on a builder
// thread's shared context, and keeps it in its shader cache, from which the
// window's own first draw with the same state then loads it.
void warm_up(const Program& program, GLenum format, const ChannelInputs& channels = {});

class Renderer {
 public:
  Renderer();  // needs a current GL context
  // Sets every input the program reads and draws over the bound framebuffer's
  // (0,0,size) viewport. A supersample (inputs.sample > 0, core/supersampling.h)
  // is added to the running mean of the samples already there: a float
  // target keeps that mean exact. The scissor, if any, holds for both.
  void draw(const Program& program, const FrameInputs& inputs, const ChannelInputs& channels, glm::ivec2 size) const;

  // Renders offscreen at `size`, in tiles no larger than the driver allows,
  // each the mean of `samples` supersamples (1: the pixel centres alone),
  // each of those at every step of `motion`'s shutter (iTime moved).
  // A tile moves gl_FragCoord by its origin; callers check that the shader
  // kind can be drawn in tiles first.
  Image render_image(const Program& program, FrameInputs inputs, const ChannelInputs& channels, glm::ivec2 size,
                     int samples = 1, const MotionBlur& motion = {}) const;
  int max_tile() const { return max_tile_; }
  void limit_tile(int pixels) { max_tile_ = std::max(1, std::min(max_tile_, pixels)); }  // tests tiling

 private:
  // The shader's own draw into the bound framebuffer.
  void draw_pass(const Program& program, const FrameInputs& inputs, const ChannelInputs& channels,
                 glm::ivec2 size) const;
  // Adds `sample_` to the mean in the bound framebuffer: mean + (sample -
  // mean) / (index + 1). A pass of the host's own, so that the shader itself
  // is never drawn with blending, which llvmpipe would compile it again for
  // (hundreds of ms on real scenes).
  void add_sample(int index, glm::ivec2 size) const;

  gl::VertexArray vao_;
  std::optional<Program> mean_;  // add_sample()'s pass
  mutable std::optional<RenderTarget> sample_;  // where a supersample is drawn before it is added
  int max_tile_ = 4096;
};

}  // namespace rm
