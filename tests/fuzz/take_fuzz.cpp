// libFuzzer target for a take's file (core/take_format.cpp), as `render
// --take` reads it, and for its replay (core/take_replay.cpp). The input is
// the file's text. Checked: no crash or hang; a refused text says why in one
// line; a take it reads has frames in the order of their times, each with a
// window size, and its text as the window writes it reads back to the same
// text (the writer's text is a fixed point). Then a replay walks it at the
// recorded rate and at another, as `render --take` does.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/take.h"

namespace {

void walk(const rm::Take& take, double fps) {
  const rm::TakeReplay replay(take, fps);
  const int frames = replay.frames();
  if (frames < 1) std::abort();
  const rm::UserUniforms none;
  int crossed = 0;
  for (int i = 0; i < std::min(frames, 64); ++i) {
    const auto [first, last] = replay.crossed(i);
    if (first > last || last > static_cast<int>(take.frames.size())) std::abort();
    crossed = last;
    const rm::FrameInputs in = rm::take_inputs_at(take, replay.wall(i), {160, 90}, none);
    if (std::isnan(in.time)) std::abort();
    take.defines_at(in.frame);
  }
  // At any rate every recorded frame is crossed (at the recorded rate, one each).
  if (frames <= 64 && crossed != static_cast<int>(take.frames.size())) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::filesystem::path folder = "/fuzz/takes";
  std::string error;
  const auto take = rm::parse_take(text, folder, &error);
  if (!take) {
    if (error.empty() || error.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  if (take->frames.empty() || !take->scene.is_absolute()) std::abort();
  for (size_t i = 0; i < take->frames.size(); ++i) {
    const rm::TakeFrame& f = take->frames[i];
    if (f.size.x <= 0 || f.size.y <= 0 || (i > 0 && f.wall < take->frames[i - 1].wall)) std::abort();
  }
  const std::string written = rm::take_text(*take, folder);
  std::string again_error;
  const auto again = rm::parse_take(written, folder, &again_error);
  if (!again || again->scene != take->scene || again->frames.size() != take->frames.size()) std::abort();
  if (rm::take_text(*again, folder) != written) std::abort();
  walk(*take, 0);
  walk(*take, 24);
  return 0;
}
