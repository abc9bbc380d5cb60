// The time stamps of the window's -v log ("... at NS"): nanoseconds of the
// steady clock, Linux's CLOCK_MONOTONIC, so that the lines of the window's
// threads and a benchmark's own readings of that clock compare.
#pragma once
#include <chrono>

namespace rm {

inline long long steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace rm
