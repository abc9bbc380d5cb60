#include "core/inputs.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace rm {

std::optional<std::string> iframe_out_of_range(double iframe) {
  if (iframe >= INT_MIN && iframe <= INT_MAX) return std::nullopt;
  char message[120];
  std::snprintf(message, sizeof message, "iFrame would be %.10g, past what an int holds (%d to %d)", iframe, INT_MIN,
                INT_MAX);
  return message;
}

void MouseState::press(glm::vec2 position) {
  held_ = true;
  clicked_this_frame_ = true;
  position_ = click_ = cursor_ = position;
}

void MouseState::move(glm::vec2 position) {
  cursor_ = position;
  if (held_) position_ = position;
}

void MouseState::release() { held_ = false; }

void MouseState::end_frame() { clicked_this_frame_ = false; }

glm::vec4 MouseState::imouse() const {
  return {position_, held_ ? click_.x : -click_.x, clicked_this_frame_ ? click_.y : -click_.y};
}

float ShaderClock::tick(Clock::time_point now) {
  const double delta = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  if (paused_) return 0.0f;
  if (delta > 0) frame_rate_ = static_cast<float>(1.0 / delta);
  time_ += delta * speed_;
  return static_cast<float>(delta * speed_);
}

glm::vec4 date_of(std::chrono::system_clock::time_point when) {
  const std::time_t seconds = std::chrono::system_clock::to_time_t(when);
  std::tm local{};
  localtime_r(&seconds, &local);
  const auto since_second = when - std::chrono::system_clock::from_time_t(seconds);
  const double fraction = std::chrono::duration<double>(since_second).count();
  const double of_day = local.tm_hour * 3600.0 + local.tm_min * 60.0 + local.tm_sec + fraction;
  return {static_cast<float>(local.tm_year + 1900), static_cast<float>(local.tm_mon),
          static_cast<float>(local.tm_mday), static_cast<float>(of_day)};
}

std::string date_text(const glm::vec4& date) {
  const int seconds = static_cast<int>(date.w);
  char out[64];
  std::snprintf(out, sizeof out, "%04d-%02d-%02dT%02d:%02d:%06.3f", static_cast<int>(date.x),
                static_cast<int>(date.y) + 1, static_cast<int>(date.z), seconds / 3600, seconds / 60 % 60,
                std::fmod(static_cast<double>(date.w), 60.0));
  return out;
}

}  // namespace rm
