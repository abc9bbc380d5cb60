#include "window/builder.h"

#include <chrono>
#include <exception>
#include <new>
#include <thread>

#include "core/address_space.h"
#include "core/gl.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rm {

namespace {

// The contexts of the build that runs on this thread: its builder's, or
// those run_jobs() lent it.
struct Contexts {
  const SharedContext* context = nullptr;
  const SharedContext* probe = nullptr;
};
thread_local Contexts current;

}  // namespace

void Builder::open(GLFWwindow* window) {
  if (context_) return;
  context_ = SharedContext::make(window, "raymarching builder");
  if (context_) probe_ = SharedContext::make(window, "raymarching builder probe");
  open_ = context_ != nullptr;
}

Builder::~Builder() {
  if (thread_.joinable()) thread_.join();
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
  if (!current.probe) return;
  current.probe->make_current();
  draw();
  current.context->make_current();
}

void Builder::run_jobs(const std::vector<std::function<void()>>& jobs, const Builder& helper) {
  std::atomic<size_t> next{0};
  auto take_jobs = [&](size_t* took = nullptr) {
    for (size_t i = next++; i < jobs.size(); i = next++) {
      jobs[i]();
      if (took) ++*took;
    }
  };
  if (jobs.size() < 2) {
    take_jobs();
    return;
  }
  std::exception_ptr beside_failed, here_failed;
  size_t beside_took = 0;
  DeepStackThread beside([&] {
    // The window opens the helper while the first program builds; a
    // background build this save put off ends at its stage under way, and
    // then leaves its contexts free (no longer running(), though still
    // busy() until the window takes it, after this build).
    while ((!helper.open_ || helper.running()) && next < jobs.size())
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (next >= jobs.size()) return;
    current = {helper.context_.get(), helper.probe_.get()};
    current.context->make_current();
    try {
      take_jobs(&beside_took);
    } catch (...) {
      beside_failed = std::current_exception();
    }
    if (beside_took > 0) glFinish();  // what it made complete for the window's context, as start()'s is
    current.context->release();
  });
  try {
    take_jobs();
  } catch (...) {
    here_failed = std::current_exception();
  }
  beside.join();
  if (beside_took > 0) job_threads_ = 2;
  if (here_failed) std::rethrow_exception(here_failed);
  if (beside_failed) std::rethrow_exception(beside_failed);
}

void Builder::start(std::function<ReloadStatus()> build) {
  job_threads_ = 1;
  error_.clear();
  done_ = false;
  cancel_ = false;
  thread_ = DeepStackThread([this, build = std::move(build)] {
    current = {context_.get(), probe_.get()};
    current.context->make_current();
    try {
      status_ = build();
    } catch (const NoRoomForDriver& e) {
      error_ = e.what();
      status_ = ReloadStatus::Failed;
    } catch (const std::bad_alloc&) {  // uncaught on this thread, it would end the window
      error_ = "not enough memory to build the scene";
      status_ = ReloadStatus::Failed;
    }
    // Shared objects are complete for another context once this one has
    // finished with them: a swap's. llvmpipe's contexts share one
    // rasterizer, so glFinish also waits for the window's tile under way
    // (seconds of a heavy shader's), which a build that swaps nothing need not.
    if (status_ == ReloadStatus::Swapped) glFinish();
    current.context->release();
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
