// FrameGraph: draws a Project's frames. It owns what the passes read and
// write: each buffer pass's pair of RGBA32F targets (ping-pong), the channel
// images, the keyboard texture and Shadertoy's samplers.
//
// One rule gives Shadertoy's order: a pass reads each buffer's latest
// finished output. A buffer drawn earlier in this frame has already swapped
// its pair, so its readers see this frame; a pass that reads itself, or a
// buffer drawn later, sees the previous frame.
#pragma once
#include <map>
#include <string>

#include "core/channels.h"
#include "core/keyboard.h"
#include "core/project.h"
#include "core/renderer.h"

namespace rm {

class FrameGraph {
 public:
  explicit FrameGraph(const Renderer& renderer);  // needs a current GL context

  // After a reload that swapped: reads the images the passes name (once per
  // file), makes targets for new buffers and frees those of buffers gone.
  // A reload keeps every remaining buffer's content. false with *error
  // ("iChannel1 of image.frag 'rock.png': why") if an image cannot be read;
  // that channel then reads transparent black.
  bool update(const Project& project, std::string* error);

  // One frame: every buffer pass into its target, then the image pass over
  // `target`'s (0,0,size) viewport. Buffers are the size of the picture; a
  // new size keeps their content where it fits.
  void draw(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target = 0);
  // Only the buffer passes: the frames before the one `render` writes.
  void draw_buffers(const Project& project, const FrameInputs& in, glm::ivec2 size);
  // The image pass alone, read back (in tiles past the driver's limit),
  // reading the buffers as they are: a screenshot must not advance them.
  Image render_image(const Project& project, const FrameInputs& in, glm::ivec2 size) const;
  // draw() into an image: buffers, then the image pass.
  Image render_frame(const Project& project, const FrameInputs& in, glm::ivec2 size);

  void restart();  // every buffer back to zero
  KeyboardState& keyboard() { return keyboard_; }
  // The latest output of a buffer pass (tests read it); 0 if none.
  GLuint buffer_texture(const fs::path& pass) const;

 private:
  struct Buffer {
    gl::Texture front, back;  // front: the latest finished output
    gl::Framebuffer front_fbo, back_fbo;
    glm::ivec2 size{0};
  };
  void resize(Buffer& buffer, glm::ivec2 size) const;
  ChannelInputs inputs_of(const Project& project, size_t pass) const;
  GLuint sampler_for(const Sampler& s) const;

  const Renderer& renderer_;
  ImageTextures images_;
  std::map<fs::path, Buffer> buffers_;
  KeyboardState keyboard_;
  gl::Texture keyboard_texture_, black_;
  gl::Sampler samplers_[3][2];  // [filter][wrap]
};

}  // namespace rm
