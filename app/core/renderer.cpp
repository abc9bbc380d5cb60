#include "core/renderer.h"

#include <algorithm>
#include <string>

namespace rm {

InputUse inputs_read(const Program& program) {
  InputUse use;
  for (const char* name : {"iTime", "iTimeDelta", "iFrame", "iFrameRate", "iDate", "iChannelTime", "u_time",
                           "u_delta", "u_frame", "u_date"})
    use.time = use.time || program.uses(name);
  use.drag = program.uses("iMouse");
  use.pointer = program.uses("u_mouse");
  return use;
}


RenderTarget::RenderTarget(int width, int height) : width_(width), height_(height) {
  color_ = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(color_.get(), 1, GL_RGBA32F, width, height);
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

Renderer::Renderer() : vao_(gl::make_vertex_array()) {
  GLint max_size = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  max_tile_ = std::max(1, std::min({max_size, viewport[0], viewport[1], 8192}));
}

void Renderer::draw(const Program& program, const FrameInputs& in, const Channels& channels, glm::ivec2 size) const {
  const float resolution[3] = {in.resolution.x, in.resolution.y, in.resolution.z};
  program.set("iResolution", resolution, 3);
  program.set("iTime", in.time);
  program.set("iTimeDelta", in.time_delta);
  program.set("iFrameRate", in.frame_rate);
  program.set("iFrame", static_cast<float>(in.frame));
  program.set("iMouse", &in.mouse.x, 4);
  program.set("iDate", &in.date.x, 4);
  program.set("iSampleRate", in.sample_rate);
  program.set("rm_FragCoordOffset", &in.frag_coord_offset.x, 2);
  // glslViewer / Book of Shaders names.
  program.set("u_resolution", resolution, 2);
  program.set("u_time", in.time);
  program.set("u_delta", in.time_delta);
  program.set("u_frame", static_cast<float>(in.frame));
  program.set("u_mouse", &in.cursor.x, 2);
  program.set("u_date", &in.date.x, 4);
  for (int i = 0; i < Channels::kCount; ++i) {
    glBindTextureUnit(static_cast<GLuint>(i), channels.texture(i));
    program.set_sampler("iChannel" + std::to_string(i), i);
    program.set_sampler("u_tex" + std::to_string(i), i);
    const glm::vec3 r = channels.resolution(i);
    program.set_element("iChannelResolution", i, &r.x, 3);
    program.set_element("iChannelTime", i, &in.time, 1);
  }
  glViewport(0, 0, size.x, size.y);
  glUseProgram(program.id());
  glBindVertexArray(vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

Image Renderer::render_image(const Program& program, FrameInputs inputs, const Channels& channels, glm::ivec2 size) const {
  const int tile = max_tile_;
  if (size.x <= tile && size.y <= tile) {
    RenderTarget target(size.x, size.y);
    target.bind();
    draw(program, inputs, channels, size);
    return target.read();
  }
  Image full{size.x, size.y, std::vector<float>(static_cast<size_t>(size.x) * size.y * 4)};
  for (int y0 = 0; y0 < size.y; y0 += tile) {
    for (int x0 = 0; x0 < size.x; x0 += tile) {
      const glm::ivec2 part(std::min(tile, size.x - x0), std::min(tile, size.y - y0));
      RenderTarget target(part.x, part.y);
      target.bind();
      inputs.frag_coord_offset = glm::vec2(x0, y0);
      draw(program, inputs, channels, part);
      glFinish();  // bound the work queued per tile on software renderers
      Image piece = target.read();
      // piece row 0 is its top, which is full-image row size.y - (y0 + part.y).
      const int top = size.y - (y0 + part.y);
      for (int y = 0; y < part.y; ++y)
        std::copy_n(&piece.rgba[static_cast<size_t>(y) * part.x * 4], static_cast<size_t>(part.x) * 4,
                    &full.rgba[(static_cast<size_t>(top + y) * size.x + x0) * 4]);
    }
  }
  return full;
}

}  // namespace rm
