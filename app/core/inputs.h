// Inputs: the values a frame hands to the shader, with Shadertoy's semantics,
// plus the small state machines (mouse, clock) the window drives them with.
#pragma once
#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace rm {

// A value of one of the shader's own uniforms (core/user_uniforms.h), as
// `render --set NAME=TEXT` gives it and a screenshot records it.
struct UniformValue {
  std::string name;
  std::vector<float> value;  // 1 to 4 components
  std::string text;          // as written: "1.5", "true", "0.1,0.2,0.3"
};

// Why a frame's iFrame, an int, cannot be `iframe` (a cast past its range is
// undefined): "iFrame would be 6e+301, past what an int holds (...)"; nothing when it can.
std::optional<std::string> iframe_out_of_range(double iframe);

struct FrameInputs {
  glm::vec3 resolution{1.0f, 1.0f, 1.0f};  // z is the pixel aspect ratio: 1
  float time = 0.0f;
  float time_delta = 1.0f / 60.0f;
  float frame_rate = 60.0f;
  int frame = 0;
  glm::vec4 mouse{0.0f};                   // Shadertoy iMouse
  glm::vec2 cursor{0.0f};                  // glslViewer u_mouse: the pointer, button or not
  glm::vec4 date{0.0f};                    // year, month from 0, day, seconds since midnight
  float sample_rate = 44100.0f;
  glm::vec2 frag_coord_offset{0.0f};       // tile origin when rendering in tiles
  int sample = 0;                          // which supersample of the picture (core/supersampling.h); 0: the pixel centres
  int cube_face = 0;                       // the face a Cube A pass draws
  std::vector<UniformValue> uniforms;      // the shader's own uniforms, set in every pass that declares them
};

// Shadertoy's iMouse: xy follows the pointer while the left button is held and
// stays after release; zw is the press position; z > 0 while held, negated
// after release; w > 0 only in the frame of the press.
class MouseState {
 public:
  void press(glm::vec2 position);
  void move(glm::vec2 position);  // any pointer motion; xy only follows while held
  void release();
  void end_frame();               // call after each rendered frame
  glm::vec4 imouse() const;
  glm::vec2 cursor() const { return cursor_; }
  bool held() const { return held_; }

 private:
  glm::vec2 position_{0.0f};
  glm::vec2 click_{0.0f};
  glm::vec2 cursor_{0.0f};
  bool held_ = false;
  bool clicked_this_frame_ = false;
};

// The shader clock: pausable, restartable, steppable while paused.
class ShaderClock {
 public:
  using Clock = std::chrono::steady_clock;
  explicit ShaderClock(Clock::time_point now = Clock::now()) : last_(now) {}
  // Advances to now; returns the shader-time delta in seconds (0 while paused).
  float tick(Clock::time_point now = Clock::now());
  void set_paused(bool paused) { paused_ = paused; }
  bool paused() const { return paused_; }
  void restart() { time_ = 0.0; frame_ = 0; }
  void step(double seconds) { time_ = std::max(0.0, time_ + seconds); }
  void seek(double seconds) { time_ = std::max(0.0, seconds); }
  // How fast shader time runs against the wall clock, within [kMinSpeed, kMaxSpeed].
  static constexpr double kMinSpeed = 0.1, kMaxSpeed = 4.0;
  void set_speed(double speed) { speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed); }
  double speed() const { return speed_; }
  void next_frame() { ++frame_; }
  double time() const { return time_; }
  int frame() const { return frame_; }
  // Shadertoy's iFrameRate: frames per second of the wall clock (not of
  // shader time, which runs at the clock's speed), at the last tick that ran
  // the clock; held while paused, when ticks only redraw the same moment.
  float frame_rate() const { return frame_rate_; }

 private:
  Clock::time_point last_;
  double time_ = 0.0;
  int frame_ = 0;
  float frame_rate_ = 60.0f;
  bool paused_ = false;
  double speed_ = 1.0;
};

// iDate for a wall-clock instant, in local time.
glm::vec4 date_of(std::chrono::system_clock::time_point when);
// An iDate as `render --date` reads it: local YYYY-MM-DDTHH:MM:SS.sss.
std::string date_text(const glm::vec4& date);

}  // namespace rm
