#include "window/display_lost.h"

#include <X11/Xlib.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "core/diagnostics.h"

// GLFW's own, from glfw3native.h, which would want Xrandr's headers for it.
extern "C" Display* glfwGetX11Display(void);

namespace rm {

namespace {

std::function<void()> last_words;
std::thread::id window_thread;
std::atomic<bool> window_ending{false};  // the window's thread is in its last words

std::string lost_line(Display* display) {
  return "raymarching: error: lost the X display " + std::string(DisplayString(display)) +
         " (its server ended, or it closed this window's connection)";
}

// The guards' state, for a handler that may only read it.
std::mutex guards_mutex;
int guards = 0;
int guarded_fd = -1;
char guarded_line[512];
size_t guarded_line_size = 0;
struct sigaction segv_before {};

void on_segv(int, siginfo_t*, void*) {
  pollfd connection{guarded_fd, POLLRDHUP, 0};
  if (guarded_fd >= 0 && poll(&connection, 1, 0) == 1 && (connection.revents & (POLLRDHUP | POLLHUP | POLLERR))) {
    [[maybe_unused]] const ssize_t said = write(STDERR_FILENO, guarded_line, guarded_line_size);
    _exit(kExitUsage);
  }
  // Not the display: the fault comes again as this returns, and crashes as before.
  sigaction(SIGSEGV, &segv_before, nullptr);
}

int display_lost(Display* display) {
  if (std::this_thread::get_id() == window_thread) {
    if (!window_ending.exchange(true) && last_words) last_words();  // once: they might meet the display again
  } else {
    // A builder's thread met it first. The window's thread meets it at its
    // next event (within 250 ms), writes what it must and ends the process;
    // this thread ends it only where the window's never comes.
    for (int waited = 0; waited < 20 && !window_ending; ++waited)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    while (window_ending) std::this_thread::sleep_for(std::chrono::seconds(1));
  }
  std::cout.flush();
  std::cerr << lost_line(display) << std::endl;
  std::_Exit(kExitUsage);  // Xlib's display cannot be torn down any more
}

}  // namespace

void on_display_lost(std::function<void()> words) {
  last_words = std::move(words);
  window_thread = std::this_thread::get_id();
  XSetIOErrorHandler(display_lost);
}

ContextMadeWhileDisplayMayGo::ContextMadeWhileDisplayMayGo() {
  Display* display = glfwGetX11Display();
  std::lock_guard<std::mutex> lock(guards_mutex);
  if (guards++ > 0 || !display) return;
  const std::string line = lost_line(display) + "\n";
  guarded_line_size = std::min(line.size(), sizeof guarded_line);
  line.copy(guarded_line, guarded_line_size);
  guarded_fd = ConnectionNumber(display);
  struct sigaction action {};
  action.sa_sigaction = on_segv;
  action.sa_flags = SA_SIGINFO;
  sigemptyset(&action.sa_mask);
  sigaction(SIGSEGV, &action, &segv_before);
}

ContextMadeWhileDisplayMayGo::~ContextMadeWhileDisplayMayGo() {
  std::lock_guard<std::mutex> lock(guards_mutex);
  if (--guards > 0 || guarded_fd < 0) return;
  sigaction(SIGSEGV, &segv_before, nullptr);
  guarded_fd = -1;
}

}  // namespace rm
