// When the X server goes away under the window (it ended, or xkill cut this
// client off), Xlib calls its I/O error handler and then ends the process
// itself, with exit(1) and words of its own: a take being recorded and the
// shots still being written were lost. The window's handler writes them
// first, says so in one line and ends with status 2, as an I/O error.
#pragma once
#include <functional>

namespace rm {

// Installs the handler for the process. `last_words` runs on the thread that
// calls this (the window's), before the process ends; another thread that
// meets the lost display first (a builder's) waits for the window's thread
// to meet it too, for 2 s.
void on_display_lost(std::function<void()> last_words);

// Mesa's GLX reads the server's replies through xcb, not Xlib, and does not
// check for a reply that never comes: a display lost while a context is
// made ends in SIGSEGV there (seen in glfwCreateWindow), not in the handler
// above. While a guard lives, a SIGSEGV when GLFW's connection to the
// X server has been hung up is taken for that: the same line and status 2. Any other
// SIGSEGV crashes as it would have. Nothing is being recorded yet while
// contexts are made.
class ContextMadeWhileDisplayMayGo {
 public:
  ContextMadeWhileDisplayMayGo();  // after glfwInit()
  ~ContextMadeWhileDisplayMayGo();
  ContextMadeWhileDisplayMayGo(const ContextMadeWhileDisplayMayGo&) = delete;
  ContextMadeWhileDisplayMayGo& operator=(const ContextMadeWhileDisplayMayGo&) = delete;
};

}  // namespace rm
