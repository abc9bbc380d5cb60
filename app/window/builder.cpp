#include "window/builder.h"

#include <iostream>
#include <new>

#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rm {

void Builder::open(GLFWwindow* window) {
  if (context_) return;
  // The window's context hints (version, profile) still hold.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  context_ = glfwCreateWindow(1, 1, "raymarching builder", nullptr, window);
  if (context_) probe_ = glfwCreateWindow(1, 1, "raymarching builder probe", nullptr, window);
  glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
}

Builder::~Builder() {
  if (thread_.joinable()) thread_.join();
  if (probe_) glfwDestroyWindow(probe_);
  if (context_) glfwDestroyWindow(context_);
}

// llvmpipe generates a program's machine code per context, and the window's
// context finds the code the builder's generated only in Mesa's shader
// cache, which Mesa writes on a thread of its own after the draw that
// generated it. Under load that thread could still be writing when the
// window drew, and the window then generated the code itself (2 of 12 code
// edits of tori with both cores busy: 132 and 151 ms in a 4x4 tile). The
// same draw in a second context stands in for the window's: it finds the
// entry if it is written, or else generates the code there, on this
// thread, which takes long enough for the first entry to be written.
void Builder::in_probe_context(const std::function<void()>& draw) {
  if (!probe_) return;
  glfwMakeContextCurrent(probe_);
  draw();
  glfwMakeContextCurrent(context_);
}

void Builder::start(std::function<ReloadStatus()> build) {
  done_ = false;
  cancel_ = false;
  thread_ = DeepStackThread([this, build = std::move(build)] {
    glfwMakeContextCurrent(context_);
    try {
      status_ = build();
    } catch (const std::bad_alloc&) {  // uncaught on this thread, it would end the window
      std::cerr << "raymarching: error: not enough memory to build the scene; the last good picture stays\n";
      status_ = ReloadStatus::Failed;
    }
    // Shared objects are complete for another context once this one has
    // finished with them: a swap's. llvmpipe's contexts share one
    // rasterizer, so glFinish also waits for the window's tile under way
    // (seconds of a heavy shader's), which a build that swaps nothing need not.
    if (status_ == ReloadStatus::Swapped) glFinish();
    glfwMakeContextCurrent(nullptr);
    done_ = true;
    glfwPostEmptyEvent();
  });
}

std::optional<ReloadStatus> Builder::finished() {
  if (!thread_.joinable() || !done_) return std::nullopt;
  thread_.join();
  return status_;
}

}  // namespace rm
