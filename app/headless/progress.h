// The progress bar of a headless run on the terminal: frames done of all,
// their rate and the time left. Nothing is shown when stderr is not a
// terminal (a log, a pipe, a test).
#pragma once
#include <chrono>
#include <string>

namespace rm {

// "[#####     ] 12/24 frames  3.1 fps  ETA 0:04" after `seconds` for `done`.
std::string progress_line(int done, int total, double seconds);

class Progress {
 public:
  explicit Progress(int total);
  // Redraws the bar with `done` frames finished; ends the line at the last.
  void show(int done);

 private:
  int total_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace rm
