#include "headless/run_guard.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "core/diagnostics.h"

namespace rm {

RunGuard::RunGuard(double seconds, std::string option)
    : option_(std::move(option)), stderr_(fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0)) {
  if (seconds > 0 || signals_.fd() >= 0) thread_ = std::thread([this, seconds] { watch(seconds); });
}

RunGuard::~RunGuard() {
  if (thread_.joinable()) {
    signals_.wake();
    thread_.join();
  }
  if (stderr_ >= 0) close(stderr_);
}

bool RunGuard::write(const std::filesystem::path& path, const std::function<bool()>& write) {
  return guard([&] {
    if (!write()) return false;
    written_.push_back(path);
    return true;
  });
}

bool RunGuard::guard(const std::function<bool()>& step) {
  std::lock_guard lock(mutex_);
  return step();
}

void RunGuard::on_end(std::function<void()> undo, std::string what) {
  std::lock_guard lock(mutex_);
  undo_.push_back(std::move(undo));
  undo_what_ = std::move(what);
}

void RunGuard::watch(double seconds) {
  // Past a few years the limit is no limit: a double that large would overflow the clock.
  const auto limit = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                            std::chrono::duration<double>(std::min(seconds, 1e8)));
  for (;;) {
    int wait_ms = -1;
    if (seconds > 0) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(limit - std::chrono::steady_clock::now());
      if (left.count() <= 0) end(0);
      wait_ms = static_cast<int>(std::min<long long>(left.count(), 1 << 30));
    }
    pollfd wake{signals_.fd(), POLLIN, 0};
    if (poll(&wake, 1, wait_ms) <= 0) continue;  // the limit (checked above), or EINTR
    if (const int signal = signals_.received()) end(signal);
    return;  // woken by the destructor: the run ended
  }
}

void RunGuard::end(int signal) {
  // With the lock no write is under way, and none starts.
  std::lock_guard lock(mutex_);
  for (const auto& undo : undo_) undo();
  const bool timed_out = signal == 0;
  if (timed_out)
    for (const auto& path : written_) {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
  const std::string frames = timed_out ? "the frames it wrote are removed"
                                       : "the " + std::to_string(written_.size()) + " frames it wrote are kept";
  const std::string why = timed_out ? "the render ran past " + option_ + " s and was stopped"
                                    : "the render was stopped by " + signal_name(signal);
  const std::string said =
      why + "; " +
      (!undo_.empty() ? undo_what_ + " is removed" : written_.empty() ? std::string("nothing was written") : frames);
  // On a terminal the line goes below the progress bar (and a ^C), not after it.
  std::fflush(stderr);  // what was said before, first
  const int to = stderr_ >= 0 ? stderr_ : STDERR_FILENO;
  dprintf(to, "%sraymarching: error: %s\n", isatty(to) ? "\n" : "", said.c_str());
  std::_Exit(timed_out ? kExitTimeout : 128 + signal);  // the GL thread may be inside a draw: no destructors
}

}  // namespace rm
