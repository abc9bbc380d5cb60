// What the benchmarks share: the wall-clock time of frames, each between two
// glFinish calls, so that the driver's queued work is counted in its frame.
#pragma once
#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace bench {

// Runs draw(i) for `warm_up` + `frames` frames; the times of the last
// `frames`, in ms, sorted.
template <typename Draw>
std::vector<double> frame_times_ms(Draw&& draw, int warm_up, int frames) {
  std::vector<double> ms;
  for (int i = 0; i < warm_up + frames; ++i) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    draw(i);
    glFinish();
    if (i >= warm_up) ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms;
}

template <typename Draw>
double median_frame_ms(Draw&& draw, int warm_up, int frames) {
  const std::vector<double> ms = frame_times_ms(draw, warm_up, frames);
  return ms[ms.size() / 2];
}

}  // namespace bench
