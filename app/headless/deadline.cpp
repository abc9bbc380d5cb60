#include "headless/deadline.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "core/diagnostics.h"

namespace rm {

Deadline::Deadline(double seconds, std::string option) : option_(std::move(option)) {
  if (seconds > 0) thread_ = std::thread([this, seconds] { watch(seconds); });
}

Deadline::~Deadline() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    done_ = true;
  }
  ended_.notify_all();
  thread_.join();
}

bool Deadline::write(const std::filesystem::path& path, const std::function<bool()>& write) {
  return guard([&] {
    if (!write()) return false;
    written_.push_back(path);
    return true;
  });
}

bool Deadline::guard(const std::function<bool()>& step) {
  std::lock_guard lock(mutex_);
  return step();
}

void Deadline::on_expiry(std::function<void()> undo, std::string what) {
  std::lock_guard lock(mutex_);
  undo_.push_back(std::move(undo));
  undo_what_ = std::move(what);
}

void Deadline::watch(double seconds) {
  std::unique_lock lock(mutex_);
  // Past a few years the limit is no limit: a double that large would overflow the clock.
  const auto limit = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                            std::chrono::duration<double>(std::min(seconds, 1e8)));
  if (ended_.wait_until(lock, limit, [this] { return done_; })) return;
  // The lock is ours: no write is under way, and none starts.
  for (const auto& undo : undo_) undo();
  for (const auto& path : written_) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
  std::fprintf(stderr, "raymarching: error: the render ran past %s s and was stopped; %s\n", option_.c_str(),
               !undo_.empty()      ? (undo_what_ + " is removed").c_str()
               : written_.empty()  ? "nothing was written"
                                   : "the frames it wrote are removed");
  std::fflush(stderr);
  std::_Exit(kExitTimeout);  // the GL thread may be inside a draw: no destructors
}

}  // namespace rm
