// Takes: what the window's inputs did, frame by frame, recorded live (F9)
// so that `render --take` can draw the same frames again offline, at any
// size, rate and quality. A take is a small JSON file next to the scene: the
// scene and its -I/-D (and --channelN), then per frame iTime, iFrame, the mouse, the keys and
// the shader's own uniforms, and the reloads and knob changes between
// frames. Only what changed since the frame before is written.
#pragma once
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "core/inputs.h"
#include "core/project.h"
#include "core/source.h"
#include "core/user_uniforms.h"

namespace rm {

struct KeyEvent {
  int code = 0;  // the browser's key code (core/keyboard.h)
  bool down = true;
};

struct TakeFrame {
  double wall = 0;     // seconds since the take started, on the window's steady clock
  glm::ivec2 size{0};  // the window's framebuffer, in pixels: what the mouse's pixels are of
  float time = 0;      // iTime
  int frame = 0;       // iFrame
  glm::vec4 mouse{0};  // iMouse, in the recorded window's pixels
  glm::vec2 cursor{0};
  std::vector<KeyEvent> keys;          // the keyboard's events before this frame, in order
  std::vector<UniformValue> uniforms;  // every value the frame had
};

// Between two frames the program changed: a save rebuilt it, or a knob (a -D)
// was set in the panel. Applies from frame `frame` on.
struct TakeEvent {
  int frame = 0;
  std::vector<Define> defines;                // the -D list from here on
  std::map<std::string, std::string> hashes;  // pass (relative to the scene's folder) -> source_hash
};

struct Take {
  std::filesystem::path scene;  // absolute once read
  std::filesystem::path media;
  std::array<std::filesystem::path, 4> channels;  // the window's --channelN (empty: none given)
  std::vector<std::filesystem::path> include_dirs;
  std::vector<std::string> undefines;  // the -U list (no control changes it)
  std::string date;    // iDate of frame 0, as `render --date` reads it
  std::vector<TakeFrame> frames;
  std::vector<TakeEvent> events;  // events[0] is frame 0's: the defines and sources it started with

  double duration() const { return frames.empty() ? 0.0 : frames.back().wall; }
  // The events' defines in force at `frame`.
  const std::vector<Define>& defines_at(int frame) const;
};

// Whole or not at all, never over an existing file ("-1" is added to the
// name instead); the path written, or nullopt with *error.
std::optional<std::filesystem::path> write_take(const std::filesystem::path& path, const Take& take,
                                                std::string* error);
std::optional<Take> read_take(const std::filesystem::path& path, std::string* error);

// The file's text and back (core/take_format.cpp): paths are stored relative
// to `folder`, the take's own, where they lie below it. parse_take checks
// every number against what it is read into, and says what it refuses in
// one line (without the file's name).
std::string take_text(const Take& take, const std::filesystem::path& folder);
std::optional<Take> parse_take(std::string_view text, const std::filesystem::path& folder, std::string* error);

// What identifies a pass's source across runs: a fingerprint of the lines
// that come from files (the pass and its includes), not of the host's lines
// or the -D defines, which a take records apart.
std::string source_hash(const Source& source);

// Each pass's source_hash, by its file relative to the image pass's folder.
std::map<std::string, std::string> pass_hashes(const Project& project);

// What differs between the sources a take was recorded with and `now`
// (pass_hashes of the project that replays it), in one sentence for one
// warning; nullopt when nothing does.
std::optional<std::string> take_source_changes(const Take& take, const std::map<std::string, std::string>& now);

// A take's inputs at `wall` seconds into it, interpolated between the two
// frames around it: iTime, the mouse while held, and the float uniforms
// linearly; the rest (the button, iFrame, int and bool uniforms) as the
// earlier frame has them. The mouse is moved from the recorded window's
// pixels to a picture of `size`. The frame counter and the events (a press, keys) are the
// caller's: they happen once, between frames (TakeReplay).
FrameInputs take_inputs_at(const Take& take, double wall, glm::ivec2 size, const UserUniforms& types);

// Walks a take frame by frame at a rate of its own: each step says what
// happened since the last one, so that a key or a click recorded once
// happens once, whatever the rate.
class TakeReplay {
 public:
  // fps 0: one frame per recorded frame, at the recorded times.
  TakeReplay(const Take& take, double fps) : take_(take), fps_(fps) {}
  int frames() const;                 // how many frames the replay has: the last at or past the take's end
  double wall(int index) const;       // when replay frame `index` falls in the take
  // The recorded frames crossed by replay frame `index`: those after the
  // previous replay frame's time, up to and including this one's.
  std::pair<int, int> crossed(int index) const;  // [first, last), recorded indices

 private:
  const Take& take_;
  double fps_;
};

}  // namespace rm
