#include "core/frame_graph.h"

#include <algorithm>
#include <cmath>

namespace rm {

namespace {

int mip_levels(glm::ivec2 size) {
  int levels = 1;
  for (int s = std::max(size.x, size.y); s > 1; s /= 2) ++levels;
  return levels;
}

// The buffers some pass samples with mipmaps: only those rebuild their levels.
bool read_with_mipmaps(const Project& project, const fs::path& buffer) {
  for (const Pass& pass : project.passes())
    for (const ChannelSpec& c : pass.channels)
      if (c.kind == ChannelSpec::Kind::Pass && c.path == buffer && c.sampler.filter == Sampler::Filter::Mipmap)
        return true;
  return false;
}

}  // namespace

FrameGraph::FrameGraph(const Renderer& renderer) : renderer_(renderer) {
  const float black[4] = {0, 0, 0, 0};
  black_ = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(black_.get(), 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(black_.get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, black);
  keyboard_texture_ = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(keyboard_texture_.get(), 1, GL_R8, KeyboardState::kKeys, 3);
  const GLenum min_filters[3] = {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
  const GLenum mag_filters[3] = {GL_NEAREST, GL_LINEAR, GL_LINEAR};
  const GLenum wraps[2] = {GL_CLAMP_TO_EDGE, GL_REPEAT};
  for (int f = 0; f < 3; ++f) {
    for (int w = 0; w < 2; ++w) {
      gl::Sampler s = gl::make_sampler();
      glSamplerParameteri(s.get(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filters[f]));
      glSamplerParameteri(s.get(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(mag_filters[f]));
      glSamplerParameteri(s.get(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wraps[w]));
      glSamplerParameteri(s.get(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wraps[w]));
      glSamplerParameteri(s.get(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wraps[w]));
      samplers_[f][w] = std::move(s);
    }
  }
}

GLuint FrameGraph::sampler_for(const Sampler& s) const {
  return samplers_[static_cast<int>(s.filter)][static_cast<int>(s.wrap)].get();
}

bool FrameGraph::update(const Project& project, std::string* error) {
  bool ok = true;
  std::vector<fs::path> images;
  for (const Pass& pass : project.passes()) {
    for (size_t c = 0; c < 4; ++c) {
      const ChannelSpec& spec = pass.channels[c];
      if (spec.kind == ChannelSpec::Kind::Image) {
        images.push_back(spec.path);
        std::string why;
        if (!images_.get(spec.path, &why) && ok) {
          *error = "iChannel" + std::to_string(c) + " of " + pass.file.filename().string() + " '" +
                   spec.path.string() + "': " + why;
          ok = false;
        }
      }
    }
    if (!pass.is_image) buffers_[pass.file];  // made at the first draw, at the picture's size
  }
  images_.keep_only(images);
  for (auto it = buffers_.begin(); it != buffers_.end();) {
    const bool used = std::any_of(project.passes().begin(), project.passes().end(),
                                  [&](const Pass& p) { return !p.is_image && p.file == it->first; });
    it = used ? std::next(it) : buffers_.erase(it);
  }
  return ok;
}

void FrameGraph::resize(Buffer& buffer, glm::ivec2 size) const {
  if (buffer.size == size) return;
  auto make = [&](gl::Texture* texture, gl::Framebuffer* fbo) {
    *texture = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture->get(), mip_levels(size), GL_RGBA32F, size.x, size.y);
    *fbo = gl::make_framebuffer();
    glNamedFramebufferTexture(fbo->get(), GL_COLOR_ATTACHMENT0, texture->get(), 0);
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fbo->get(), GL_COLOR, 0, zero);  // buffers start at zero
  };
  gl::Texture front, back;
  gl::Framebuffer front_fbo, back_fbo;
  make(&front, &front_fbo);
  make(&back, &back_fbo);
  if (buffer.front) {  // keep the content where it fits
    const glm::ivec2 kept = glm::min(size, buffer.size);
    glCopyImageSubData(buffer.front.get(), GL_TEXTURE_2D, 0, 0, 0, 0, front.get(), GL_TEXTURE_2D, 0, 0, 0, 0, kept.x,
                       kept.y, 1);
  }
  buffer.front = std::move(front);
  buffer.back = std::move(back);
  buffer.front_fbo = std::move(front_fbo);
  buffer.back_fbo = std::move(back_fbo);
  buffer.size = size;
}

ChannelInputs FrameGraph::inputs_of(const Project& project, size_t pass) const {
  ChannelInputs inputs;
  for (size_t c = 0; c < 4; ++c) {
    const ChannelSpec& spec = project.passes()[pass].channels[c];
    ChannelInput& in = inputs[c];
    in.texture = black_.get();
    in.sampler = sampler_for(spec.sampler);
    switch (spec.kind) {
      case ChannelSpec::Kind::Image:
        // update() read it; an image that failed reads black.
        if (const auto* it = images_.find(spec.path)) {
          in.texture = it->texture.get();
          in.resolution = it->resolution;
        }
        break;
      case ChannelSpec::Kind::Pass:
        if (auto it = buffers_.find(spec.path); it != buffers_.end() && it->second.front) {
          in.texture = it->second.front.get();
          in.resolution = glm::vec3(it->second.size, 1.0f);
        }
        break;
      case ChannelSpec::Kind::Keyboard:
        in.texture = keyboard_texture_.get();
        in.resolution = glm::vec3(KeyboardState::kKeys, 3.0f, 1.0f);
        break;
      default:
        break;
    }
  }
  return inputs;
}

void FrameGraph::draw_buffers(const Project& project, const FrameInputs& in, glm::ivec2 size) {
  if (project.reads_keyboard())
    glTextureSubImage2D(keyboard_texture_.get(), 0, 0, 0, KeyboardState::kKeys, 3, GL_RED, GL_UNSIGNED_BYTE,
                        keyboard_.texels().data());
  FrameInputs buffer_in = in;
  buffer_in.resolution = glm::vec3(size, 1.0f);
  buffer_in.frag_coord_offset = glm::vec2(0.0f);
  for (size_t i = 0; i + 1 < project.passes().size(); ++i) {
    const Pass& pass = project.passes()[i];
    Buffer& buffer = buffers_[pass.file];
    resize(buffer, size);
    glBindFramebuffer(GL_FRAMEBUFFER, buffer.back_fbo.get());
    renderer_.draw(*pass.scene->program(), buffer_in, inputs_of(project, i), size);
    std::swap(buffer.front, buffer.back);
    std::swap(buffer.front_fbo, buffer.back_fbo);
    if (read_with_mipmaps(project, pass.file)) glGenerateTextureMipmap(buffer.front.get());
  }
}

void FrameGraph::draw(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target) {
  draw_buffers(project, in, size);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  renderer_.draw(*project.image_program(), in, inputs_of(project, project.passes().size() - 1), size);
}

Image FrameGraph::render_image(const Project& project, const FrameInputs& in, glm::ivec2 size) const {
  return renderer_.render_image(*project.image_program(), in, inputs_of(project, project.passes().size() - 1), size);
}

Image FrameGraph::render_frame(const Project& project, const FrameInputs& in, glm::ivec2 size) {
  draw_buffers(project, in, size);
  return render_image(project, in, size);
}

void FrameGraph::restart() {
  const float zero[4] = {0, 0, 0, 0};
  for (auto& [file, buffer] : buffers_) {
    if (!buffer.front) continue;
    glClearNamedFramebufferfv(buffer.front_fbo.get(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(buffer.back_fbo.get(), GL_COLOR, 0, zero);
  }
  keyboard_.clear();
}

GLuint FrameGraph::buffer_texture(const fs::path& pass) const {
  auto it = buffers_.find(pass);
  return it == buffers_.end() ? 0 : it->second.front.get();
}

}  // namespace rm
