#include "headless/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rm {

namespace {

// 0:04, 12:30, 1:02:03.
std::string clock_time(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

}  // namespace

std::string progress_line(int done, int total, double seconds) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? std::clamp(done, 0, total) * kWidth / total : kWidth;
  std::string line = "[" + std::string(static_cast<size_t>(filled), '#') +
                     std::string(static_cast<size_t>(kWidth - filled), ' ') + "] " + std::to_string(done) + "/" +
                     std::to_string(total) + " frames";
  char rate[64];
  if (done > 0 && seconds > 0) {
    const double fps = done / seconds;
    std::snprintf(rate, sizeof rate, "  %.*f fps", fps < 10 ? 2 : 1, fps);
    line += rate;
    line += done < total ? "  ETA " + clock_time((total - done) / fps) : "  in " + clock_time(seconds);
  } else {
    line += "  ETA -:--";
  }
  return line;
}

Progress::Progress(int total) : total_(total), terminal_(isatty(STDERR_FILENO)) {}

void Progress::show(int done) {
  if (!terminal_) return;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // Clear to the end of the line: a shorter line must not leave the last one's tail.
  std::fprintf(stderr, "\r%s\033[K", progress_line(done, total_, seconds).c_str());
  if (done >= total_) std::fputc('\n', stderr);
  std::fflush(stderr);
}

}  // namespace rm
