#include "core/wake_on_readable.h"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <cstdint>

namespace rm {

WakeOnReadable::WakeOnReadable(int fd, std::function<void()> wake) : fd_(fd), wake_(std::move(wake)) {
  if (fd_ < 0) return;
  control_ = eventfd(0, EFD_CLOEXEC);
  if (control_ < 0) return;  // no thread: the loop keeps asking on its timer
  thread_ = std::thread([this] { run(); });
}

WakeOnReadable::~WakeOnReadable() {
  if (thread_.joinable()) {
    stop_ = true;
    const uint64_t one = 1;
    (void)!write(control_, &one, sizeof one);
    thread_.join();
  }
  if (control_ >= 0) close(control_);
}

void WakeOnReadable::rearm() {
  if (!fired_.exchange(false)) return;  // a write per wake, not per turn of the loop
  const uint64_t one = 1;
  (void)!write(control_, &one, sizeof one);
}

void WakeOnReadable::run() {
  bool armed = true;
  for (;;) {
    pollfd fds[2] = {{control_, POLLIN, 0}, {fd_, POLLIN, 0}};
    if (poll(fds, armed ? 2 : 1, -1) < 0) continue;  // EINTR
    if (fds[0].revents & POLLIN) {
      uint64_t count = 0;
      (void)!read(control_, &count, sizeof count);
      if (stop_) return;
      armed = true;
      continue;  // the loop may have read the descriptor meanwhile: poll it again
    }
    if (armed && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) {
      armed = false;
      fired_ = true;
      wake_();
    }
  }
}

}  // namespace rm
