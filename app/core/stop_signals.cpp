#include "core/stop_signals.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string>

namespace rm {

namespace {

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

// The process's pipe, kept once made (StopSignals::prepare).
std::mutex g_pipe_mutex;
int g_pipe[2] = {-1, -1};

// The pipe's end for the handler while a StopSignals lives: writing to a
// pipe is async-signal-safe.
int g_write_end = -1;
std::array<struct sigaction, kSignals.size()> g_before;
std::array<bool, kSignals.size()> g_caught{};

void on_signal(int signal) {
  const int saved = errno;
  const unsigned char number = static_cast<unsigned char>(signal);
  [[maybe_unused]] const ssize_t sent = g_write_end >= 0 ? write(g_write_end, &number, 1) : 0;
  errno = saved;
}

}  // namespace

void StopSignals::prepare() {
  std::lock_guard<std::mutex> lock(g_pipe_mutex);
  if (g_pipe[0] < 0 && pipe2(g_pipe, O_CLOEXEC | O_NONBLOCK) != 0) g_pipe[0] = g_pipe[1] = -1;
}

StopSignals::StopSignals() {
  prepare();
  {
    std::lock_guard<std::mutex> lock(g_pipe_mutex);
    pipe_[0] = g_pipe[0];
    pipe_[1] = g_pipe[1];
  }
  if (pipe_[0] < 0) return;
  g_write_end = pipe_[1];
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_RESETHAND;  // the second signal acts as if none were caught
  for (size_t i = 0; i < kSignals.size(); ++i) {
    g_caught[i] = sigaction(kSignals[i], nullptr, &g_before[i]) == 0 && g_before[i].sa_handler != SIG_IGN;
    if (g_caught[i]) sigaction(kSignals[i], &action, nullptr);
  }
}

StopSignals::~StopSignals() {
  if (pipe_[0] < 0) return;
  for (size_t i = 0; i < kSignals.size(); ++i)
    if (g_caught[i]) sigaction(kSignals[i], &g_before[i], nullptr);
  g_write_end = -1;
  // Kept for the next: what this one was sent is not the next one's.
  unsigned char left = 0;
  while (read(pipe_[0], &left, 1) == 1) {
  }
}

int StopSignals::received() {
  unsigned char number = 0;
  while (signal_ == 0 && pipe_[0] >= 0 && read(pipe_[0], &number, 1) == 1)
    if (number != 0) signal_ = number;
  return signal_;
}

void StopSignals::wake() {
  const unsigned char none = 0;
  [[maybe_unused]] const ssize_t sent = pipe_[1] >= 0 ? write(pipe_[1], &none, 1) : 0;
}

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

}  // namespace rm
