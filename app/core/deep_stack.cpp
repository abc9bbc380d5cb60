#include "core/deep_stack.h"

#include <algorithm>
#include <optional>
#include <system_error>
#include <utility>

#include "core/address_space.h"

namespace rm {

size_t deep_stack_bytes() {
  constexpr size_t kDefaultStack = size_t{8} << 20;
  const auto kib = address_space_limit_kib();
  if (!kib) return kDeepStack;
  return std::clamp(size_t(*kib / 16) << 10, kDefaultStack, kDeepStack);
}

DeepStackThread::DeepStackThread(std::function<void()> work, size_t bytes)
    : work_(std::make_unique<std::function<void()>>(std::move(work))) {
  auto call = [](void* w) -> void* {
    (*static_cast<std::function<void()>*>(w))();
    return nullptr;
  };
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  int error = pthread_attr_setstacksize(&attr, bytes);
  if (error == 0) error = pthread_create(&thread_, &attr, call, work_.get());
  pthread_attr_destroy(&attr);
  if (error != 0) error = pthread_create(&thread_, nullptr, call, work_.get());  // the default stack, then
  if (error != 0) throw std::system_error(error, std::generic_category());  // as std::thread's
  running_ = true;
}

DeepStackThread& DeepStackThread::operator=(DeepStackThread&& other) noexcept {
  thread_ = other.thread_;
  running_ = std::exchange(other.running_, false);
  work_ = std::move(other.work_);
  return *this;
}

DeepStackThread::~DeepStackThread() {
  if (running_) join();
}

void DeepStackThread::join() {
  pthread_join(thread_, nullptr);
  running_ = false;
}

void run_with_deep_stack(const std::function<void()>& work, size_t bytes) {
  std::optional<DeepStackThread> thread;
  try {
    thread.emplace(work, bytes);
  } catch (const std::system_error&) {
    work();  // no thread to be had at all: the caller's stack, rather than nothing
    return;
  }
  thread->join();
}

}  // namespace rm
