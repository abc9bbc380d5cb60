#include "core/frame_graph.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rm {

namespace {

int mip_levels(glm::ivec2 size) {
  int levels = 1;
  for (int s = std::max(size.x, size.y); s > 1; s /= 2) ++levels;
  return levels;
}

int shape_index(ChannelSpec::Shape shape) { return static_cast<int>(shape); }

}  // namespace

FrameGraph::FrameGraph(const Renderer& renderer) : renderer_(renderer) {
  const float black[4] = {0, 0, 0, 0};
  black_[0] = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(black_[0].get(), 1, GL_RGBA8, 1, 1);
  glTextureSubImage2D(black_[0].get(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, black);
  black_[1] = gl::make_texture(GL_TEXTURE_CUBE_MAP);
  glTextureStorage2D(black_[1].get(), 1, GL_RGBA8, 1, 1);
  for (int f = 0; f < 6; ++f) glTextureSubImage3D(black_[1].get(), 0, 0, 0, f, 1, 1, 1, GL_RGBA, GL_FLOAT, black);
  black_[2] = gl::make_texture(GL_TEXTURE_3D);
  glTextureStorage3D(black_[2].get(), 1, GL_RGBA8, 1, 1, 1);
  glTextureSubImage3D(black_[2].get(), 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, black);
  set_sampling_state();
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
  images_changed_ = false;
  std::vector<ChannelSpec> images;
  mipmapped_.clear();
  for (const Pass& pass : project.passes()) {
    for (size_t c = 0; c < 4; ++c) {
      const ChannelSpec& spec = pass.channels[c];
      if (spec.kind == ChannelSpec::Kind::Pass && spec.sampler.filter == Sampler::Filter::Mipmap)
        mipmapped_.push_back(spec.path);
      if (spec.kind != ChannelSpec::Kind::Image) continue;
      images.push_back(spec);
      std::string why;
      bool reread = false;
      images_.get(spec, &why, &reread);
      if (reread) {  // a new picture: what static passes drew from it is stale
        images_changed_ = true;
        for (auto& [file, buffer] : buffers_) buffer.drawn_generation = -1;
      }
      if (!why.empty() && ok) {
        *error = "iChannel" + std::to_string(c) + " of " + pass.file.filename().string() + " '" + spec.path.string() +
                 "': " + why;
        ok = false;
      }
    }
    if (!pass.is_image) buffers_[pass.file];  // made at the first draw
  }
  images_.keep_only(images);
  static_.clear();
  for (const Pass& pass : project.passes()) {
    const InputUse use = inputs_read(*pass.scene->program());
    bool fixed = !pass.is_image && !use.time && !use.drag && !use.pointer;
    for (const ChannelSpec& c : pass.channels)
      fixed = fixed && (c.kind == ChannelSpec::Kind::None || c.kind == ChannelSpec::Kind::Image ||
                        (c.kind == ChannelSpec::Kind::Pass &&
                         std::find(static_.begin(), static_.end(), c.path) != static_.end()));
    if (fixed) static_.push_back(pass.file);
  }
  for (auto it = buffers_.begin(); it != buffers_.end();) {
    const bool used = std::any_of(project.passes().begin(), project.passes().end(),
                                  [&](const Pass& p) { return !p.is_image && p.file == it->first; });
    it = used ? std::next(it) : buffers_.erase(it);
  }
  return ok;
}

void FrameGraph::resize(Buffer& buffer, glm::ivec2 size, bool cube) const {
  if (buffer.size == size && buffer.cube == cube) return;
  const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  auto make = [&](gl::Texture* texture, std::array<gl::Framebuffer, 6>* fbos) {
    *texture = gl::make_texture(target);
    glTextureStorage2D(texture->get(), mip_levels(size), format_of(cube), size.x, size.y);
    const float zero[4] = {0, 0, 0, 0};
    for (int f = 0; f < (cube ? 6 : 1); ++f) {
      gl::Framebuffer& fbo = (*fbos)[static_cast<size_t>(f)];
      fbo = gl::make_framebuffer();
      if (cube) glNamedFramebufferTextureLayer(fbo.get(), GL_COLOR_ATTACHMENT0, texture->get(), 0, f);
      else glNamedFramebufferTexture(fbo.get(), GL_COLOR_ATTACHMENT0, texture->get(), 0);
      glClearNamedFramebufferfv(fbo.get(), GL_COLOR, 0, zero);  // buffers start at zero
    }
  };
  gl::Texture front, back;
  std::array<gl::Framebuffer, 6> front_fbo, back_fbo;
  make(&front, &front_fbo);
  make(&back, &back_fbo);
  if (buffer.front && buffer.cube == cube) {  // keep the content where it fits
    const glm::ivec2 kept = glm::min(size, buffer.size);
    glCopyImageSubData(buffer.front.get(), target, 0, 0, 0, 0, front.get(), target, 0, 0, 0, 0, kept.x, kept.y,
                       cube ? 6 : 1);
  }
  buffer.cube = cube;
  buffer.front = std::move(front);
  buffer.back = std::move(back);
  buffer.front_fbo = std::move(front_fbo);
  buffer.back_fbo = std::move(back_fbo);
  buffer.size = size;
}

std::map<fs::path, FrameGraph::PassState> FrameGraph::pass_states(const Project& project) const {
  std::map<fs::path, PassState> out;
  for (size_t i = 0; i < project.passes().size(); ++i) {
    const Pass& pass = project.passes()[i];
    out[pass.file] = {pass.is_image ? RenderTarget::kFormat : format_of(pass.cube), inputs_of(project, i), pass.channels};
  }
  return out;
}

FrameGraph::StandIns FrameGraph::stand_ins(bool cubemap, const std::array<ChannelSpec, 4>& channels,
                                           const ImageTextures::HeldImages& held) const {
  StandIns out;
  out.state.format = cubemap ? format_of(true) : RenderTarget::kFormat;
  // A texture like the graph's, of as many mip levels. Its size matters
  // only as a power of two or not, which llvmpipe's code depends on. The
  // window's builder warms up with the images it reads itself; an image's
  // stand-in is for one the graph holds, bound anew (the same file on
  // another channel, or with another sampler): of its size. Without one,
  // the guess is Shadertoy's: its images, cube maps, volumes and Cube A
  // faces are all powers of two. A picture's size is rarely one.
  auto make = [&](GLenum target, GLenum format, glm::ivec3 size, int levels) {
    gl::Texture texture = gl::make_texture(target);
    if (target == GL_TEXTURE_3D) glTextureStorage3D(texture.get(), levels, format, size.x, size.y, size.z);
    else glTextureStorage2D(texture.get(), levels, format, size.x, size.y);
    out.textures.push_back(std::move(texture));
    return out.textures.back().get();
  };
  const glm::ivec2 odd(3), even(4);
  constexpr GLenum kTargets[3] = {GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D};
  for (size_t c = 0; c < 4; ++c) {
    const ChannelSpec& spec = channels[c];
    ChannelInput& in = out.state.channels[c];
    const GLenum target = kTargets[shape_index(spec.shape)];
    in.texture = black_[shape_index(spec.shape)].get();
    in.sampler = sampler_for(spec.sampler);
    in.sampler_name = spec.sampler_name;
    switch (spec.kind) {
      case ChannelSpec::Kind::Image: {
        const auto image = held.find(ImageTextures::key_of(spec));
        const glm::ivec3 size = image != held.end() ? glm::max(image->second.size, 1) : glm::ivec3(even, even.x);
        in.texture = make(target, GL_RGBA16F, size, mip_levels(glm::ivec2(std::max({size.x, size.y, size.z}))));
        break;
      }
      case ChannelSpec::Kind::Pass: {
        const bool cube = spec.shape == ChannelSpec::Shape::Cube;
        // A buffer of a fixed size: its sides, powers of two or not, as a small texture's.
        const BufferSize& own = spec.buffer_size;
        auto side = [&](int n) { return (n & (n - 1)) == 0 ? even.x : odd.x; };
        const glm::ivec2 size = cube ? even : own.width > 0 ? glm::ivec2(side(own.width), side(own.height)) : odd;
        in.texture = make(target, format_of(cube), glm::ivec3(size, 1), mip_levels(size));
        break;
      }
      case ChannelSpec::Kind::Keyboard:
        in.texture = make(GL_TEXTURE_2D, GL_R8, glm::ivec3(KeyboardState::kKeys, 3, 1), 1);
        break;
      default: break;
    }
  }
  return out;
}

ChannelInputs FrameGraph::inputs_of(const Project& project, size_t pass) const {
  ChannelInputs inputs;
  for (size_t c = 0; c < 4; ++c) {
    const ChannelSpec& spec = project.passes()[pass].channels[c];
    ChannelInput& in = inputs[c];
    in.texture = black_[shape_index(spec.shape)].get();
    in.sampler = sampler_for(spec.sampler);
    in.sampler_name = spec.sampler_name;
    switch (spec.kind) {
      case ChannelSpec::Kind::Image:
        // update() read it; an image that failed reads black.
        if (const auto* it = images_.find(spec)) {
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

void FrameGraph::time_passes(bool on, bool finish) {
  timing_ = on;
  finish_ = finish;
  times_.clear();
}

template <typename Draw>
void FrameGraph::timed(const Project& project, size_t index, glm::ivec2 size, Draw draw) {
  if (!timing_) {
    draw();
    return;
  }
  while (queries_.size() <= index) queries_.push_back(gl::make_query(GL_TIME_ELAPSED));
  if (finish_) glFinish();  // nothing earlier may still run inside this pass
  const auto start = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, queries_[index].get());
  draw();
  if (finish_) glFinish();
  glEndQuery(GL_TIME_ELAPSED);
  PassTime t;
  t.pass = project.passes()[index].file;
  t.size = size;
  t.index = index;
  if (finish_) t.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  times_.push_back(t);
}

std::vector<FrameGraph::PassTime> FrameGraph::pass_times() const {
  std::vector<PassTime> out = times_;
  for (PassTime& t : out) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(queries_[t.index].get(), GL_QUERY_RESULT, &ns);
    t.gpu_ms = static_cast<double>(ns) / 1e6;
  }
  return out;
}

// The size of one of the pass's targets: a cube face's, the buffer's own
// (fixed, or a share of the picture's), or the picture's.
static glm::ivec2 face_size(const Pass& pass, glm::ivec2 picture) {
  if (pass.cube) return glm::ivec2(pass.cube_size);
  if (pass.size.width > 0) return {pass.size.width, pass.size.height};
  if (pass.size.scale > 0) return glm::max(glm::ivec2(1), glm::ivec2(glm::round(glm::dvec2(picture) * pass.size.scale)));
  return picture;
}

glm::ivec2 FrameGraph::pass_size(const Project& project, size_t index, glm::ivec2 picture) const {
  const Pass& pass = project.passes()[index];
  const glm::ivec2 face = face_size(pass, picture);
  return pass.cube ? glm::ivec2(face.x, 6 * face.y) : face;
}

bool FrameGraph::begin_pass(const Project& project, size_t index, glm::ivec2 picture) {
  const Pass& pass = project.passes()[index];
  Buffer& buffer = buffers_[pass.file];
  const glm::ivec2 size = face_size(pass, picture);
  if (buffer.size != size || buffer.cube != pass.cube) buffer.drawn_generation = -1;
  resize(buffer, size, pass.cube);
  const bool fixed = std::find(static_.begin(), static_.end(), pass.file) != static_.end();
  if (!fixed || buffer.drawn_generation != pass.scene->generation()) return true;
  // A pass it reads drawn since (a buffer of another size, after a resize)
  // makes its picture stale too; else its picture is still right.
  return std::any_of(pass.channels.begin(), pass.channels.end(), [&](const ChannelSpec& c) {
    const auto read = buffers_.find(c.path);
    return c.kind == ChannelSpec::Kind::Pass && read != buffers_.end() && read->second.drawn_at > buffer.drawn_at;
  });
}

void FrameGraph::draw_pass_region(const Project& project, size_t index, const FrameInputs& in, glm::ivec4 region) {
  const Pass& pass = project.passes()[index];
  Buffer& buffer = buffers_[pass.file];
  const glm::ivec2 size = buffer.size;
  FrameInputs pass_in = in;
  pass_in.resolution = glm::vec3(size, 1.0f);
  pass_in.frag_coord_offset = glm::vec2(0.0f);
  pass_in.sample = 0;  // a buffer is data that later frames read, not a picture to smooth
  const ChannelInputs inputs = inputs_of(project, index);
  const int faces = pass.cube ? 6 : 1;
  const bool whole = region == glm::ivec4(0, 0, size.x, faces * size.y);
  auto draw = [&] {
    if (!whole) glEnable(GL_SCISSOR_TEST);
    for (int face = 0; face < faces; ++face) {
      // The region's rows on this face (faces are stacked, face 0 at the bottom).
      const int bottom = std::max(region.y, face * size.y), top = std::min(region.y + region.w, (face + 1) * size.y);
      if (bottom >= top) continue;
      if (!whole) glScissor(region.x, bottom - face * size.y, region.z, top - bottom);
      pass_in.cube_face = face;
      glBindFramebuffer(GL_FRAMEBUFFER, buffer.back_fbo[static_cast<size_t>(face)].get());
      renderer_.draw(*pass.scene->program(), pass_in, inputs, size);
    }
    if (!whole) glDisable(GL_SCISSOR_TEST);
  };
  // Timed only whole: one query per pass and frame.
  if (whole) timed(project, index, size, draw);
  else draw();
}

void FrameGraph::end_pass(const Project& project, size_t index) {
  const Pass& pass = project.passes()[index];
  Buffer& buffer = buffers_[pass.file];
  buffer.drawn_generation = pass.scene->generation();  // whole: a pass left in parts is drawn again
  buffer.drawn_at = ++draws_;
  std::swap(buffer.front, buffer.back);
  std::swap(buffer.front_fbo, buffer.back_fbo);
  if (std::find(mipmapped_.begin(), mipmapped_.end(), pass.file) != mipmapped_.end())
    glGenerateTextureMipmap(buffer.front.get());
}

void FrameGraph::begin_frame(const Project& project) {
  times_.clear();
  if (project.reads_keyboard())
    glTextureSubImage2D(keyboard_texture_.get(), 0, 0, 0, KeyboardState::kKeys, 3, GL_RED, GL_UNSIGNED_BYTE,
                        keyboard_.texels().data());
}

void FrameGraph::draw_buffers(const Project& project, const FrameInputs& in, glm::ivec2 size) {
  begin_frame(project);
  for (size_t i = 0; i + 1 < project.passes().size(); ++i) {
    if (!begin_pass(project, i, size)) continue;
    const glm::ivec2 whole = pass_size(project, i, size);
    draw_pass_region(project, i, in, {0, 0, whole.x, whole.y});
    end_pass(project, i);
  }
}

void FrameGraph::draw(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target) {
  draw_buffers(project, in, size);
  draw_image(project, in, size, target, {0, 0, size.x, size.y});
}

void FrameGraph::draw_image(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target,
                            glm::ivec4 region) {
  const size_t image = project.passes().size() - 1;
  glBindFramebuffer(GL_FRAMEBUFFER, target);
  const bool part = region != glm::ivec4(0, 0, size.x, size.y);
  if (part) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(region.x, region.y, region.z, region.w);
  }
  timed(project, image, size, [&] { renderer_.draw(*project.image_program(), in, inputs_of(project, image), size); });
  if (part) glDisable(GL_SCISSOR_TEST);
}

Image FrameGraph::render_image(const Project& project, const FrameInputs& in, glm::ivec2 size, int samples,
                               const MotionBlur& motion) const {
  return renderer_.render_image(*project.image_program(), in, inputs_of(project, project.passes().size() - 1), size,
                                samples, motion);
}

Image FrameGraph::render_frame(const Project& project, const FrameInputs& in, glm::ivec2 size, int samples,
                               const MotionBlur& motion) {
  draw_buffers(project, in, size);
  Image image;
  timed(project, project.passes().size() - 1, size, [&] { image = render_image(project, in, size, samples, motion); });  // with the read-back
  return image;
}

void FrameGraph::restart() {
  const float zero[4] = {0, 0, 0, 0};
  for (auto& [file, buffer] : buffers_) {
    buffer.drawn_generation = -1;
    if (!buffer.front) continue;
    for (int f = 0; f < (buffer.cube ? 6 : 1); ++f) {
      glClearNamedFramebufferfv(buffer.front_fbo[static_cast<size_t>(f)].get(), GL_COLOR, 0, zero);
      glClearNamedFramebufferfv(buffer.back_fbo[static_cast<size_t>(f)].get(), GL_COLOR, 0, zero);
    }
  }
  keyboard_.clear();
}

bool FrameGraph::buffers_sized_for(const Project& project, glm::ivec2 size) const {
  return std::all_of(project.passes().begin(), project.passes().end(), [&](const Pass& pass) {
    if (pass.is_image || pass.cube || pass.size.width > 0) return true;  // of a size of their own
    const auto it = buffers_.find(pass.file);
    return it != buffers_.end() && it->second.size == face_size(pass, size);
  });
}

void FrameGraph::swap_buffers(BufferSet& set) { std::swap(buffers_, set.buffers_); }

GLuint FrameGraph::buffer_texture(const fs::path& pass) const {
  auto it = buffers_.find(pass);
  return it == buffers_.end() ? 0 : it->second.front.get();
}

}  // namespace rm
