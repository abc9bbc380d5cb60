// SharedContext: a GL context that shares the window's objects, made on the
// main thread and used on a thread of its own (a builder's).
//
// GLFW makes such a context only as a hidden window, and each window it makes
// weighs every framebuffer config the driver offers: 46 ms apiece on
// llvmpipe under Xvfb, and the window needs four, two before its first
// build can start. Where GLFW made the window's context with GLX, the
// context is made with GLX from the window's own config instead (about 8
// ms), and made current without a drawable: a builder draws only into its
// own framebuffer objects. Elsewhere (an EGL context) it is a hidden window
// still.
#pragma once
#include <memory>

struct GLFWwindow;

namespace rm {

class SharedContext {
 public:
  // On the main thread, with `window`'s context current; nullptr if the
  // driver made none. `name` titles a hidden window.
  static std::unique_ptr<SharedContext> make(GLFWwindow* window, const char* name);
  virtual ~SharedContext() = default;

  // On the thread that uses it: this context becomes current there, or none.
  virtual void make_current() const = 0;
  virtual void release() const = 0;
  // Made with GLX from the window's config, not as a hidden window.
  virtual bool direct() const = 0;
};

}  // namespace rm
