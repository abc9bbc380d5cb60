// DeepStackThread: work that recurses past the 8 MiB a thread gets by
// default (as the GL driver's compiler does on a deep shader) runs to its
// end, and the thread joins and moves as a std::thread does.
#include "core/deep_stack.h"

#include <gtest/gtest.h>

#include <atomic>

namespace rm {
namespace {

// Recurses `levels` deep on frames of about 1 KB that the compiler must
// keep: 32,768 levels need 32 MiB of stack.
int deep(int levels) {
  volatile char frame[1024];
  frame[levels % sizeof frame] = static_cast<char>(levels);
  if (levels == 0) return 0;
  return deep(levels - 1) + (frame[levels % sizeof frame] == static_cast<char>(levels) ? 1 : 0);
}

TEST(DeepStack, WorkThatRecursesPastEightMiBRunsToItsEnd) {
  int reached = 0;
  run_with_deep_stack([&] { reached = deep(32768); });
  EXPECT_EQ(reached, 32768);
}

TEST(DeepStack, AThreadJoinsAndMovesAsAStdThreadDoes) {
  std::atomic<int> runs{0};
  DeepStackThread none;
  EXPECT_FALSE(none.joinable());
  DeepStackThread thread([&] { ++runs; });
  EXPECT_TRUE(thread.joinable());
  none = std::move(thread);
  EXPECT_FALSE(thread.joinable());
  ASSERT_TRUE(none.joinable());
  none.join();
  EXPECT_FALSE(none.joinable());
  EXPECT_EQ(runs, 1);
  {
    DeepStackThread joined_when_gone([&] { ++runs; });
  }
  EXPECT_EQ(runs, 2);
}

}  // namespace
}  // namespace rm
