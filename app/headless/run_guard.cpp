#include "headless/run_guard.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/diagnostics.h"

namespace rm {

namespace {

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

// The guard's pipe, for the handler: writing to a pipe is async-signal-safe,
// and the watch thread does the rest.
int g_wake = -1;
struct sigaction g_before[kSignals.size()];

void on_signal(int signal) {
  const int saved = errno;
  const unsigned char number = static_cast<unsigned char>(signal);
  [[maybe_unused]] const ssize_t sent = g_wake >= 0 ? write(g_wake, &number, 1) : 0;
  errno = saved;
}

}  // namespace

RunGuard::RunGuard(double seconds, std::string option) : option_(std::move(option)) {
  if (pipe2(wake_, O_CLOEXEC | O_NONBLOCK) != 0) return;  // no watch: the run has no limit, signals end it as ever
  g_wake = wake_[1];
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  // A signal ignored when the run began stays ignored (nohup's SIGHUP; a
  // shell script's background job's SIGINT), as in any Unix tool.
  for (size_t i = 0; i < kSignals.size(); ++i)
    if (sigaction(kSignals[i], nullptr, &g_before[i]) == 0 && g_before[i].sa_handler != SIG_IGN)
      sigaction(kSignals[i], &action, nullptr);
  thread_ = std::thread([this, seconds] { watch(seconds); });
}

RunGuard::~RunGuard() {
  if (!thread_.joinable()) return;
  const unsigned char ended = 0;
  [[maybe_unused]] const ssize_t sent = ::write(wake_[1], &ended, 1);
  thread_.join();
  for (size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &g_before[i], nullptr);
  g_wake = -1;
  close(wake_[0]);
  close(wake_[1]);
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
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(limit - std::chrono::steady_clock::now());
      if (left.count() <= 0) end(0);
      wait_ms = static_cast<int>(std::min<long long>(left.count(), 1 << 30));
    }
    pollfd wake{wake_[0], POLLIN, 0};
    if (poll(&wake, 1, wait_ms) <= 0) continue;  // the limit (checked above), or EINTR
    unsigned char number = 0;
    if (read(wake_[0], &number, 1) != 1) continue;
    if (number == 0) return;  // the run ended
    end(number);
  }
}

void RunGuard::end(int signal) {
  // With the lock no write is under way, and none starts.
  std::lock_guard lock(mutex_);
  for (const auto& undo : undo_) undo();
  std::string said;
  if (signal == 0) {
    for (const auto& path : written_) {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
    said = "the render ran past " + option_ + " s and was stopped; " +
           (!undo_.empty()     ? undo_what_ + " is removed"
            : written_.empty() ? std::string("nothing was written")
                               : std::string("the frames it wrote are removed"));
  } else {
    said = std::string("the render was stopped by SIG") + sigabbrev_np(signal) + "; " +
           (!undo_.empty()     ? undo_what_ + " is removed"
            : written_.empty() ? std::string("nothing was written")
                               : "the " + std::to_string(written_.size()) + " frames it wrote are kept");
  }
  std::fprintf(stderr, "raymarching: error: %s\n", said.c_str());
  std::fflush(stderr);
  std::_Exit(signal == 0 ? kExitTimeout : 128 + signal);  // the GL thread may be inside a draw: no destructors
}

}  // namespace rm
