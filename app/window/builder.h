// Builder: runs a build (a reload's Project::prepare: the preprocessor,
// glslang, the driver's compile and link, a warm-up draw; or a background
// job's) on a thread of its own, in a GL context that shares the window's
// objects (window/shared_context.h). The window keeps drawing the running program
// meanwhile, and commits the new one when the build has finished. The
// window has two: one for saves, one for the builds nobody waits for.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/deep_stack.h"
#include "core/scene.h"
#include "window/shared_context.h"

struct GLFWwindow;

namespace rm {

class Builder {
 public:
  // On the main thread, with `window`'s context current.
  explicit Builder(GLFWwindow* window) { open(window); }
  // One not available() until open(): its contexts can be made later.
  Builder() = default;
  void open(GLFWwindow* window);
  ~Builder();  // waits for a build under way
  Builder(const Builder&) = delete;
  Builder& operator=(const Builder&) = delete;

  // False when no shared context could be made: the caller builds in place.
  bool available() const { return context_ != nullptr; }
  bool busy() const { return thread_.joinable(); }
  // A build not finished yet (busy() also holds for one finished and not yet taken).
  bool running() const { return thread_.joinable() && !done_; }
  // Runs `build` on the builder's thread; wakes the event loop when done.
  void start(std::function<ReloadStatus()> build);
  // The finished build's status, once; nullopt while one runs or none did.
  std::optional<ReloadStatus> finished();
  // Why the finished build failed, where the build could not say it in its
  // diagnostics (out of memory, or of room for the driver); else empty.
  const std::string& error() const { return error_; }
  // Asks the build under way to stop where it can (it reads cancelled()).
  void cancel() { cancel_ = true; }
  bool cancelled() const { return cancel_; }

  // On the builder's thread, during a build: runs `draw` in a second context
  // that shares the window's objects, then makes the builder's current
  // again. A warm-up drawn once more there makes sure that Mesa's cache
  // holds the new program's machine code before the window draws it
  // (see the .cpp). Without that context, `draw` is not run. On a thread
  // of run_jobs() that works in another builder's contexts, that builder's.
  void in_probe_context(const std::function<void()>& draw);

  // On the builder's thread, during a build: runs `jobs` (core/scene.h's
  // RunJobs) here and on a second thread in helper's contexts, once helper
  // is open and its own build (put off by the save) has ended, each thread
  // taking the next job not taken. The window keeps
  // `helper` idle meanwhile: it starts and takes background builds only
  // while the saves' builder is idle.
  void run_jobs(const std::vector<std::function<void()>>& jobs, const Builder& helper);
  // How many threads the latest build's run_jobs() ran jobs on (1 or 2);
  // read once the build has finished.
  int job_threads() const { return job_threads_; }

 private:
  std::unique_ptr<SharedContext> context_, probe_;
  std::atomic<bool> open_{false};  // read by another builder's run_jobs()
  int job_threads_ = 1;
  DeepStackThread thread_;  // the driver's compiler recurses on deep shaders
  std::atomic<bool> done_{false}, cancel_{false};
  ReloadStatus status_ = ReloadStatus::Unchanged;
  std::string error_;
};

}  // namespace rm
