#include "window/display_lost.h"

#include <X11/Xlib.h>

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

int display_lost(Display* display) {
  static bool ending = false;  // last_words met the lost display again
  if (std::this_thread::get_id() == window_thread) {
    if (last_words && !std::exchange(ending, true)) last_words();
  } else {
    // The window's thread meets it at its next event (within 250 ms) and
    // ends the process; this is for a window's thread that never does.
    std::this_thread::sleep_for(std::chrono::seconds(2));
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
