// A time limit for a headless run (`render --timeout`). A draw call cannot be
// interrupted, so when the limit passes a watch thread ends the process: one
// line on stderr, every file the run wrote removed, and exit status
// kExitTimeout. A file being written is finished first, so no half file is
// left under any name; a video being encoded is abandoned (on_expiry).
#pragma once
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace rm {

class Deadline {
 public:
  // seconds <= 0: no limit. `option` names it in the message ("--timeout 2").
  Deadline(double seconds, std::string option);
  ~Deadline();  // the run ended in time: stops the watch
  Deadline(const Deadline&) = delete;
  Deadline& operator=(const Deadline&) = delete;

  // Runs `write`, which writes `path`, whole: the limit waits for it. The
  // file is removed if the limit passes later in the run.
  bool write(const std::filesystem::path& path, const std::function<bool()>& write);
  // Runs `step` whole: the limit waits for it (a frame sent to ffmpeg).
  bool guard(const std::function<bool()>& step);
  // Runs `undo` if the limit passes: for what is not a whole file yet (a
  // video being encoded), which the message names as `what`.
  void on_expiry(std::function<void()> undo, std::string what);

 private:
  void watch(double seconds);

  std::string option_;
  std::mutex mutex_;  // held by a write, and by the watch when it ends the run
  std::condition_variable ended_;
  bool done_ = false;
  std::vector<std::filesystem::path> written_;
  std::vector<std::function<void()>> undo_;
  std::string undo_what_;
  std::thread thread_;
};

}  // namespace rm
