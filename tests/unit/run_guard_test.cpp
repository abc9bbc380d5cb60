// The guard's last word: what ends a headless run says so on the stderr the
// run began with, even while a library's stderr is shut.
#include "headless/run_guard.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/diagnostics.h"
#include "core/stderr_shut.h"

namespace rm {
namespace {

// A channel image read while --timeout passes: OIIO's read shuts stderr
// (libpng's chatter), and the timeout's line used to be lost with it.
TEST(RunGuardDeathTest, TheLimitIsSaidWhileStderrIsShut) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        RunGuard guard(0.2, "--timeout 0.2");
        const StderrShut quiet;
        std::this_thread::sleep_for(std::chrono::seconds(30));
      },
      testing::ExitedWithCode(kExitTimeout),
      "raymarching: error: the render ran past --timeout 0\\.2 s and was stopped; nothing was written");
}

TEST(StderrShutTest, StderrIsShutWhileItLivesAndBackAfter) {
  testing::internal::CaptureStderr();
  {
    const StderrShut quiet;
    std::fputs("libpng error: IDAT: CRC error\n", stderr);
    std::fflush(stderr);
  }
  std::fputs("said after\n", stderr);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "said after\n");
}

}  // namespace
}  // namespace rm
