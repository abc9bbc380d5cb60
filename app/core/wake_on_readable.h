// WakeOnReadable: a thread that calls `wake` when a file descriptor turns
// readable, so that an event loop can sleep until a file changes instead of
// waking on a timer to ask (the window passes glfwPostEmptyEvent, and the
// watcher's inotify descriptor). It calls `wake` once, then waits for
// rearm(): the loop reads the descriptor, and the thread would otherwise
// spin on data still unread.
#pragma once
#include <atomic>
#include <functional>
#include <thread>

namespace rm {

class WakeOnReadable {
 public:
  // fd < 0: nothing to wait on; active() is false and no thread starts.
  WakeOnReadable(int fd, std::function<void()> wake);
  ~WakeOnReadable();
  WakeOnReadable(const WakeOnReadable&) = delete;
  WakeOnReadable& operator=(const WakeOnReadable&) = delete;

  bool active() const { return thread_.joinable(); }
  // After the loop has read what woke it: the next readable data wakes it again.
  void rearm();

 private:
  void run();
  int fd_;
  int control_ = -1;  // an eventfd: rearm() and the destructor write to it
  std::function<void()> wake_;
  std::atomic<bool> fired_{false}, stop_{false};
  std::thread thread_;
};

}  // namespace rm
