// What ends a headless run before its end: `render --timeout` passing, or a
// signal that asks it to stop (core/stop_signals.h). A draw call cannot be
// interrupted, so a watch thread ends the process: one line on stderr,
// nothing partial left, and its own exit status. A file being written is
// finished first, so no half file is left under any name; a video being
// encoded is abandoned (on_end).
//  - The limit passes: every file the run wrote is removed; kExitTimeout.
//  - A signal: the frames written whole are kept (a sequence stopped at
//    frame 40 keeps 0 to 39); 128 + the signal's number, as a shell reports it.
#pragma once
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/stop_signals.h"

namespace rm {

class RunGuard {
 public:
  // seconds <= 0: no limit. `option` names it in the message ("--timeout 2").
  RunGuard(double seconds, std::string option);
  ~RunGuard();  // the run ended: stops the watch, and signals act as before
  RunGuard(const RunGuard&) = delete;
  RunGuard& operator=(const RunGuard&) = delete;

  // Runs `write`, which writes `path`, whole: the end waits for it. The
  // file is removed if the limit passes later in the run.
  bool write(const std::filesystem::path& path, const std::function<bool()>& write);
  // Runs `step` whole: the end waits for it (a frame sent to ffmpeg).
  bool guard(const std::function<bool()>& step);
  // Runs `undo` if the run is ended: for what is not a whole file yet (a
  // video being encoded), which the message names as `what`.
  void on_end(std::function<void()> undo, std::string what);

 private:
  void watch(double seconds);
  [[noreturn]] void end(int signal);  // 0: the limit passed

  std::string option_;
  // stderr as the run began: the last line is said there even while a
  // library's stderr is shut (core/stderr_shut.h).
  int stderr_;
  StopSignals signals_;
  std::mutex mutex_;  // held by a write, and by the watch when it ends the run
  std::vector<std::filesystem::path> written_;
  std::vector<std::function<void()>> undo_;
  std::string undo_what_;
  std::thread thread_;
};

}  // namespace rm
