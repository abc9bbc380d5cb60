// Replaying a take (core/take.h): its inputs between two recorded frames,
// and which recorded frames each frame of a replay at another rate crosses.
#include <algorithm>
#include <climits>
#include <cmath>

#include "core/take.h"

namespace rm {

const std::vector<Define>& Take::defines_at(int frame) const {
  static const std::vector<Define> none;
  const std::vector<Define>* out = &none;
  for (const TakeEvent& e : events)
    if (e.frame <= frame) out = &e.defines;
  return *out;
}

FrameInputs take_inputs_at(const Take& take, double wall, glm::ivec2 size, const UserUniforms& types) {
  const auto& frames = take.frames;
  // The last frame at or before `wall`, and the one after it.
  auto after = std::upper_bound(frames.begin(), frames.end(), wall,
                                [](double w, const TakeFrame& f) { return w < f.wall; });
  const TakeFrame& a = after == frames.begin() ? frames.front() : *std::prev(after);
  const TakeFrame& b = after == frames.end() ? a : *after;
  const double span = b.wall - a.wall;
  const float k = span > 0 ? static_cast<float>(std::clamp((wall - a.wall) / span, 0.0, 1.0)) : 0.0f;

  FrameInputs in;
  // A restart or a seek back is a jump, not a slope.
  in.time = b.time >= a.time ? glm::mix(a.time, b.time, k) : a.time;
  in.frame = a.frame;
  in.mouse = a.mouse;
  const bool held = a.mouse.z > 0 && b.mouse.z > 0;
  if (held) in.mouse = glm::vec4(glm::mix(glm::vec2(a.mouse), glm::vec2(b.mouse), k), a.mouse.z, a.mouse.w);
  in.mouse.w = a.mouse.w > 0 ? -a.mouse.w : a.mouse.w;  // a press happens in one frame: the caller's (TakeReplay)
  in.cursor = glm::mix(a.cursor, b.cursor, k);
  const glm::vec2 scale = glm::vec2(size) / glm::vec2(a.size);
  in.resolution = glm::vec3(size, 1.0f);
  in.mouse *= glm::vec4(scale, scale);
  in.cursor *= scale;
  for (const UniformValue& u : a.uniforms) {
    UniformValue v = u;
    const UserUniform* type = types.find(u.name);
    auto next = std::find_if(b.uniforms.begin(), b.uniforms.end(), [&](const UniformValue& o) { return o.name == u.name; });
    const bool continuous = type && type->type != UserUniform::Type::Int && type->type != UserUniform::Type::Bool;
    if (continuous && next != b.uniforms.end() && next->value.size() == u.value.size() && k > 0) {
      for (size_t i = 0; i < v.value.size(); ++i) v.value[i] = glm::mix(u.value[i], next->value[i], k);
      v.text = uniform_value_text(type->type, v.value);
    }
    in.uniforms.push_back(std::move(v));
  }
  return in;
}

int TakeReplay::frames() const {
  if (fps_ <= 0) return static_cast<int>(take_.frames.size());
  // Up to the take's end or just past it, so that the last replay frame
  // crosses the last recorded frames (a key pressed in the take's last
  // 1/fps s happens too). A take of hours at a high rate is more frames
  // than an int holds: say the most.
  const double count = std::ceil(take_.duration() * fps_ - 1e-9) + 1;
  return count < INT_MAX ? static_cast<int>(count) : INT_MAX;
}

double TakeReplay::wall(int index) const {
  if (fps_ <= 0) return take_.frames[static_cast<size_t>(std::clamp(index, 0, frames() - 1))].wall;
  return index / fps_;
}

std::pair<int, int> TakeReplay::crossed(int index) const {
  if (fps_ <= 0) return {index, index + 1};
  auto count_until = [&](double w) {  // recorded frames at or before w
    return static_cast<int>(std::upper_bound(take_.frames.begin(), take_.frames.end(), w,
                                             [](double x, const TakeFrame& f) { return x < f.wall; }) -
                            take_.frames.begin());
  };
  const int first = index == 0 ? 0 : count_until(wall(index - 1));
  return {first, count_until(wall(index))};
}

}  // namespace rm
