// Threads with a stack deep enough for compilers that recurse once per
// level of a shader's trees: glslang in its worker, and the GL driver's
// compiler wherever a program is built (Mesa's overflowed an 8 MiB stack on
// a chain of 7,000 single-use variables, which validation now refuses
// anyway: this is the margin under that limit). std::thread cannot choose
// its stack. Only the pages a thread touches are ever backed by memory.
#pragma once
#include <pthread.h>

#include <cstddef>
#include <functional>
#include <memory>

namespace rm {

constexpr size_t kDeepStack = size_t{256} << 20;

// The stack a deep thread asks for: kDeepStack, or under an address-space
// limit (ulimit -v) a sixteenth of the limit, at least the default 8 MiB.
// The whole stack counts against the limit, touched or not, and the window
// runs four at once (its own, a build's two threads, a background build's):
// at 256 MiB each they left a 1 GB limit too little room for the driver.
size_t deep_stack_bytes();

// A thread running `work` on a stack of `bytes`, joined as a std::thread is.
// Where no such stack can be had, it gets the default one.
class DeepStackThread {
 public:
  DeepStackThread() = default;
  explicit DeepStackThread(std::function<void()> work, size_t bytes = deep_stack_bytes());
  DeepStackThread(DeepStackThread&& other) noexcept { *this = std::move(other); }
  DeepStackThread& operator=(DeepStackThread&& other) noexcept;  // only onto one not joinable
  ~DeepStackThread();  // joins one still running
  DeepStackThread(const DeepStackThread&) = delete;
  DeepStackThread& operator=(const DeepStackThread&) = delete;

  bool joinable() const { return running_; }
  void join();

 private:
  pthread_t thread_{};
  bool running_ = false;
  std::unique_ptr<std::function<void()>> work_;  // where the thread finds it, whatever moves
};

// Runs `work` on a thread with a stack of `bytes`, and waits for it; on this
// thread where no thread can be started.
void run_with_deep_stack(const std::function<void()>& work, size_t bytes = deep_stack_bytes());

}  // namespace rm
