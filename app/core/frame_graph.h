// FrameGraph: draws a Project's frames. It owns what the passes read and
// write: each buffer pass's pair of targets (ping-pong), the channel images,
// cube maps and volumes, the keyboard texture and Shadertoy's samplers.
//
// One rule gives Shadertoy's order: a pass reads each buffer's latest
// finished output. A buffer drawn earlier in this frame has already swapped
// its pair, so its readers see this frame; a pass that reads itself, or a
// buffer drawn later, sees the previous frame.
#pragma once
#include <array>
#include <map>
#include <vector>
#include <string>

#include "core/channels.h"
#include "core/keyboard.h"
#include "core/project.h"
#include "core/renderer.h"

namespace rm {

class FrameGraph {
 public:
  explicit FrameGraph(const Renderer& renderer);  // needs a current GL context

  // After a reload: reads the images the passes name (once per file, and
  // again when it changed on disk), makes targets for new buffers and frees
  // those of buffers gone. A reload keeps every remaining buffer's content.
  // false with *error ("iChannel1 of image.frag 'rock.png': why") if an
  // image cannot be read: the channel keeps the last good picture of that
  // file, or reads transparent black if there was none.
  bool update(const Project& project, std::string* error);
  // Whether the latest update() read an image file anew (it changed on
  // disk): the window calls update() after every watched change, even one
  // that left every pass's text as it was, and redraws when this is true.
  bool images_changed() const { return images_changed_; }
  // What the images were read from, and the next update()'s images read on
  // another thread (ImageTextures::stale): the window's builder reads them.
  ImageTextures::HeldImages images_held() const { return images_.held(); }
  void hand_over(std::vector<std::pair<ChannelSpec, ImageTextures::Entry>> read) { images_.hand_over(std::move(read)); }

  // One frame: every buffer pass into its target, then the image pass over
  // `target`'s (0,0,size) viewport. Buffers are the size of the picture, or
  // of their own (Pass::size); a new size keeps their content where it
  // fits. A Cube A pass draws its six faces at its own size.
  void draw(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target = 0);
  // Only the buffer passes: the frames before the one `render` writes.
  void draw_buffers(const Project& project, const FrameInputs& in, glm::ivec2 size);
  // draw_buffers in parts, for a window that draws a heavy buffer over
  // several turns of its loop: begin_frame once (the keyboard), then for
  // each buffer pass begin_pass (false: a static pass whose picture is still
  // right, not to be drawn), draw_pass_region for parts of its target of
  // pass_size (a Cube A pass's six faces stacked, +X at the bottom, so that
  // a region may span faces), and end_pass, which
  // makes what was drawn the pass's latest output. Its readers see the
  // previous output until then.
  void begin_frame(const Project& project);
  bool begin_pass(const Project& project, size_t index, glm::ivec2 picture);
  glm::ivec2 pass_size(const Project& project, size_t index, glm::ivec2 picture) const;
  void draw_pass_region(const Project& project, size_t index, const FrameInputs& in, glm::ivec4 region);
  void end_pass(const Project& project, size_t index);
  // Only the image pass, over `region` (x, y, width, height) of `target`'s
  // (0,0,size) viewport: one tile of a picture drawn in parts. gl_FragCoord
  // is the whole picture's, so every kind of shader can be drawn this way.
  // in.sample > 0 blends a supersample into what `target` holds.
  void draw_image(const Project& project, const FrameInputs& in, glm::ivec2 size, GLuint target, glm::ivec4 region);
  // The image pass alone, read back (in tiles past the driver's limit),
  // reading the buffers as they are: a screenshot must not advance them.
  // Each pixel is the mean of `samples` supersamples (core/supersampling.h).
  // With `motion`, the samples also spread over the shutter's time.
  Image render_image(const Project& project, const FrameInputs& in, glm::ivec2 size, int samples = 1,
                     const MotionBlur& motion = {}) const;
  // draw() into an image: buffers once (at the frame's time), then the image
  // pass's samples.
  Image render_frame(const Project& project, const FrameInputs& in, glm::ivec2 size, int samples = 1,
                     const MotionBlur& motion = {});

  // Per-pass timing, for the HUD and the benchmarks: GPU time from a
  // GL_TIME_ELAPSED query around each pass and, with `finish`, the wall
  // clock around each pass followed by glFinish (llvmpipe rasterises on
  // threads its queries do not see; the wall clock is the one to trust there).
  struct PassTime {
    fs::path pass;
    glm::ivec2 size{0};  // of the target it drew: a cube's face, a buffer's own size, the picture's
    double gpu_ms = 0;
    double wall_ms = 0;  // 0 without `finish`
    size_t index = 0;    // in the project's draw order
  };
  void time_passes(bool on, bool finish = false);
  // The passes of the latest frame drawn with timing on, in draw order
  // (waits for the queries' results). A static pass not drawn again is not there.
  std::vector<PassTime> pass_times() const;

  void restart();  // every buffer back to zero
  KeyboardState& keyboard() { return keyboard_; }
  // What each pass draws into and reads now, by file: its target's format
  // and the textures and samplers bound to its channels (a builder warms a
  // new program up with the same ones). The image pass's target is the
  // caller's; a RenderTarget's format is given.
  struct PassState {
    GLenum format = RenderTarget::kFormat;
    ChannelInputs channels;
    std::array<ChannelSpec, 4> specs;  // what the channels were bound for
  };
  std::map<fs::path, PassState> pass_states(const Project& project) const;
  // A PassState for a pass the graph holds nothing for yet (a new pass, or
  // every pass of the first program): its target's format (a Cube A pass's
  // when `cubemap`), and textures of the format, shape and sampler the graph
  // will bind for `channels`, so that a warm-up draw makes llvmpipe generate
  // the code the pass's first draw needs. Safe on a builder's thread: it
  // reads only what the constructor made.
  struct StandIns {
    PassState state;
    std::vector<gl::Texture> textures;  // owned, for the warm-up's time
  };
  // `held`: the images the graph holds, as images_held() gave them.
  StandIns stand_ins(bool cubemap, const std::array<ChannelSpec, 4>& channels,
                     const ImageTextures::HeldImages& held = {}) const;
  // The latest output of a buffer pass (tests read it); 0 if none.
  GLuint buffer_texture(const fs::path& pass) const;

  // Whether every buffer pass sized by the picture holds one of `size`,
  // so that the image pass at `size` reads them as they are. The window's
  // buffers are the size of its last picture, which the frame budget may
  // have drawn at a lower scale.
  bool buffers_sized_for(const Project& project, glm::ivec2 size) const;
  // Buffer targets apart from the graph's own. A picture of another size
  // than the one the buffers hold (a screenshot while the budget scales the
  // window's, or at --shot-scale) draws every buffer pass anew into a set of
  // its own, swapped in for its draws and out again, so that the window's
  // buffers stay as they are. Only for a project whose buffers do not feed
  // later frames: drawn anew, they are what they would have been.
  class BufferSet;
  void swap_buffers(BufferSet& set);

 private:
  // A buffer pass's pair of targets: RGBA32F pictures, or for a Cube A pass
  // RGBA16F cube maps (one framebuffer per face).
  static GLenum format_of(bool cube) { return cube ? GL_RGBA16F : GL_RGBA32F; }
  struct Buffer {
    bool cube = false;
    int drawn_generation = -1;  // the pass's program generation its content was drawn with; -1: none
    long long drawn_at = 0;     // when it was last drawn, in draws_: a static reader drawn before is stale
    gl::Texture front, back;  // front: the latest finished output
    std::array<gl::Framebuffer, 6> front_fbo, back_fbo;
    glm::ivec2 size{0};
  };
  void resize(Buffer& buffer, glm::ivec2 size, bool cube) const;
  // Runs `draw` (pass `index` of `project`, into a target of `size`), timed
  // when timing is on.
  template <typename Draw>
  void timed(const Project& project, size_t index, glm::ivec2 size, Draw draw);
  ChannelInputs inputs_of(const Project& project, size_t pass) const;
  GLuint sampler_for(const Sampler& s) const;

 public:
  class BufferSet {  // after Buffer, which it holds
    friend class FrameGraph;
    std::map<fs::path, Buffer> buffers_;
  };

 private:
  const Renderer& renderer_;
  ImageTextures images_;
  std::map<fs::path, Buffer> buffers_;
  std::vector<fs::path> mipmapped_;  // the buffers some pass samples with mipmaps
  // Passes whose picture cannot change from frame to frame: they read no
  // clock, mouse or keyboard, not themselves, and only images and other
  // such passes. Each is drawn again only after a reload, a resize, a
  // restart, or a draw of a pass it reads (one of another size, resized); a
  // static Cube A sky is drawn once.
  std::vector<fs::path> static_;
  long long draws_ = 0;  // the buffer passes drawn so far
  KeyboardState keyboard_;
  gl::Texture keyboard_texture_;
  gl::Texture black_[3];  // a transparent black texel per shape: flat, cube, volume
  gl::Sampler samplers_[3][2];  // [filter][wrap]
  bool images_changed_ = false;
  bool timing_ = false, finish_ = false;
  std::vector<gl::Query> queries_;   // one per pass
  std::vector<PassTime> times_;      // the wall clock and pass of each query
};

}  // namespace rm
