#include "window/display_lost.h"

#include <X11/Xlib.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <utility>

#include "core/diagnostics.h"

namespace rm {

namespace {

std::function<void()> last_words;
std::thread::id window_thread;
std::atomic<bool> window_ending{false};  // the window's thread is in its last words

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
  std::cerr << "raymarching: error: lost the X display " << DisplayString(display)
            << " (its server ended, or it closed this window's connection)" << std::endl;
  std::_Exit(kExitUsage);  // Xlib's display cannot be torn down any more
}

}  // namespace

void on_display_lost(std::function<void()> words) {
  last_words = std::move(words);
  window_thread = std::this_thread::get_id();
  XSetIOErrorHandler(display_lost);
}

}  // namespace rm
