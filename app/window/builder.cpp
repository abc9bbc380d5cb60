#include "window/builder.h"

#include <iostream>
#include <new>

#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rm {

Builder::Builder(GLFWwindow* window) {
  // The window's context hints (version, profile) still hold.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  context_ = glfwCreateWindow(1, 1, "raymarching builder", nullptr, window);
  glfwWindowHint(GLFW_VISIBLE, GLFW_TRUE);
}

Builder::~Builder() {
  if (thread_.joinable()) thread_.join();
  if (context_) glfwDestroyWindow(context_);
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
