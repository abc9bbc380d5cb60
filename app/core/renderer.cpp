#include "core/renderer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "core/channel_spec.h"
#include "core/supersampling.h"

namespace rm {

RenderTarget::RenderTarget(int width, int height) : width_(width), height_(height) {
  color_ = gl::make_texture(GL_TEXTURE_2D);
  // Out of memory is this call's to say, not the debug output's: it is off
  // for the call, and the error flag read after it (earlier errors were said).
  const bool debug_output = glIsEnabled(GL_DEBUG_OUTPUT);
  if (debug_output) glDisable(GL_DEBUG_OUTPUT);
  while (glGetError() != GL_NO_ERROR) {
  }
  glTextureStorage2D(color_.get(), 1, kFormat, width, height);
  const GLenum error = glGetError();
  if (debug_output) glEnable(GL_DEBUG_OUTPUT);
  if (error == GL_OUT_OF_MEMORY) throw std::bad_alloc();
  fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo_.get(), GL_COLOR_ATTACHMENT0, color_.get(), 0);
}

void RenderTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get()); }

Image RenderTarget::read() const {
  Image gl_rows{width_, height_, std::vector<float>(static_cast<size_t>(width_) * height_ * 4)};
  glNamedFramebufferReadBuffer(fbo_.get(), GL_COLOR_ATTACHMENT0);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, gl_rows.rgba.data());
  return gl_rows.flipped();
}

void set_sampling_state() { glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS); }

// A pass's one triangle with `program`, under the logic op COPY: it writes
// what the shader writes, as no logic op does (and a float target ignores
// it). It is there for llvmpipe, which generates an opaque shader's machine
// code twice, for whole tiles and for tiles cut by an edge, and a shader that
// is not opaque once: a fresh shader is ready 30-40% sooner (abstract 225 ->
// 140 ms), and its frames cost the same (docs/performance-history.md).
// No program stays current after its draw. The driver keeps a program that
// is deleted while current in some context until that context binds
// another, and ImGui's backend saves GL_CURRENT_PROGRAM and binds it back
// after drawing the interface: a scene program dropped from the cache while
// the window held its picture was then freed by ImGui's own bind, and bound
// back by a dead name (GL_INVALID_VALUE in glUseProgram).
static void draw_triangle_with(GLuint program) {
  glUseProgram(program);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_COPY);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_COLOR_LOGIC_OP);
  glUseProgram(0);
}

void bind_channels(const Program& program, const ChannelInputs& channels) {
  for (int i = 0; i < 4; ++i) {
    const ChannelInput& c = channels[static_cast<size_t>(i)];
    glBindTextureUnit(static_cast<GLuint>(i), c.texture);
    glBindSampler(static_cast<GLuint>(i), c.sampler);
    program.set_sampler("iChannel" + std::to_string(i), i);
    program.set_sampler("u_tex" + std::to_string(i), i);
  }
  glBindTextureUnit(kNothingBoundUnit, 0);
  glBindSampler(kNothingBoundUnit, 0);
  for (const auto& [name, uniform] : program.uniforms())
    if (uniform.sampler && channel_of_sampler(name) < 0) program.set_sampler(name, kNothingBoundUnit);
  for (int i = 0; i < 4; ++i)
    if (const std::string& name = channels[static_cast<size_t>(i)].sampler_name; !name.empty())
      program.set_sampler(name, i);
}

void warm_up(const Program& program, GLenum format, const ChannelInputs& channels) {
  const gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.get(), 1, format, 1, 1);
  const gl::Framebuffer target = gl::make_framebuffer();
  glNamedFramebufferTexture(target.get(), GL_COLOR_ATTACHMENT0, texture.get(), 0);
  const gl::VertexArray vertices = gl::make_vertex_array();
  set_sampling_state();  // llvmpipe's code depends on it too
  bind_channels(program, channels);
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  glViewport(0, 0, 1, 1);
  glBindVertexArray(vertices.get());
  draw_triangle_with(program.id());  // the state llvmpipe's code depends on, as the pass is drawn
  glFinish();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Renderer::Renderer() : vao_(gl::make_vertex_array()) {
  GLint max_size = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  max_tile_ = std::max(1, std::min({max_size, viewport[0], viewport[1], 8192}));
  Source mean;
  mean.version_line = kHostVersionLine;
  mean.text = mean.version_line +
              "\nuniform sampler2D sample_;\nout vec4 color;\n"
              "void main() { color = texelFetch(sample_, ivec2(gl_FragCoord.xy), 0); }\n";
  mean.files = {"<host: add_sample>"};
  Diagnostics unexpected;
  mean_ = Program::build(mean, &unexpected);
  if (!mean_) {  // the host's own four lines: a driver that rejects them cannot draw anything
    std::fprintf(stderr, "raymarching: error: the driver rejects the host's sample pass: %s\n", join(unexpected).c_str());
    std::abort();
  }
  mean_->set_sampler("sample_", 0);
}

void Renderer::draw(const Program& program, const FrameInputs& in, const ChannelInputs& channels, glm::ivec2 size) const {
  if (in.sample == 0) {
    draw_pass(program, in, channels, size);
    return;
  }
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  if (!sample_ || glm::ivec2(sample_->width(), sample_->height()) != size) sample_.emplace(size.x, size.y);
  sample_->bind();
  draw_pass(program, in, channels, size);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  add_sample(in.sample, size);
}

void Renderer::draw_pass(const Program& program, const FrameInputs& in, const ChannelInputs& channels,
                         glm::ivec2 size) const {
  set_host_inputs(program, in);
  for (const UniformValue& u : in.uniforms) program.set(u.name, u.value.data(), static_cast<int>(u.value.size()));
  bind_channels(program, channels);
  for (int i = 0; i < 4; ++i) {
    const glm::vec3& resolution = channels[static_cast<size_t>(i)].resolution;
    program.set_element("iChannelResolution", i, &resolution.x, 3);
    program.set("u_tex" + std::to_string(i) + "Resolution", &resolution.x, 2);  // glslViewer's name
  }
  glViewport(0, 0, size.x, size.y);
  glBindVertexArray(vao_.get());
  draw_triangle_with(program.id());
}

void Renderer::add_sample(int index, glm::ivec2 size) const {
  glViewport(0, 0, size.x, size.y);
  glUseProgram(mean_->id());
  glBindTextureUnit(0, sample_->texture());
  glBindSampler(0, 0);
  glBindVertexArray(vao_.get());
  glEnable(GL_BLEND);  // mean * (1 - weight) + sample * weight
  glBlendColor(0.0f, 0.0f, 0.0f, sample_weight(index));
  glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
  glUseProgram(0);  // as after every draw (draw_triangle_with)
}

Image Renderer::render_image(const Program& program, FrameInputs inputs, const ChannelInputs& channels, glm::ivec2 size,
                             int samples, const MotionBlur& motion) const {
  // Every sample of a tile into its target, the later ones into the mean.
  const int draws = motion.draws(samples);
  auto draw_samples = [&](const RenderTarget& target, glm::ivec2 part) {
    for (int s = 0; s < draws; ++s) {
      FrameInputs moved = inputs;
      moved.sample = s;
      const double offset = motion_offset(s, motion);
      if (offset != 0 && motion.move) motion.move(moved, offset);
      else moved.time = static_cast<float>(inputs.time + offset);
      target.bind();
      draw(program, moved, channels, part);
      if (draws > 1) glFinish();  // bound the work queued on software renderers
    }
  };
  const int tile = max_tile_;
  if (size.x <= tile && size.y <= tile) {
    RenderTarget target(size.x, size.y);
    draw_samples(target, size);
    return target.read();
  }
  Image full{size.x, size.y, std::vector<float>(static_cast<size_t>(size.x) * size.y * 4)};
  for (int y0 = 0; y0 < size.y; y0 += tile) {
    for (int x0 = 0; x0 < size.x; x0 += tile) {
      const glm::ivec2 part(std::min(tile, size.x - x0), std::min(tile, size.y - y0));
      RenderTarget target(part.x, part.y);
      inputs.frag_coord_offset = glm::vec2(x0, y0);
      draw_samples(target, part);
      glFinish();  // bound the work queued per tile on software renderers
      paste(full, target.read(), x0, y0);
    }
  }
  return full;
}

}  // namespace rm
