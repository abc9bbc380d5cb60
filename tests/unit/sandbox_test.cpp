// The sandbox that glslang runs in: what the work returns comes back whole,
// and work that runs too long, allocates too much or crashes is reported as
// such while the caller lives on.
#include "glslang_worker/sandbox.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <thread>
#include <vector>

namespace rm {
namespace {

TEST(Sandbox, ReturnsWhatTheWorkReturnsWhole) {
  // Larger than a pipe holds: the parent must read while the child writes.
  std::string big(3u << 20, 'x');
  big[12345] = '\n';
  const SandboxResult r = run_sandboxed([&] { return big; });
  EXPECT_EQ(r.status, SandboxResult::Status::Ok);
  EXPECT_EQ(r.output, big);
}

TEST(Sandbox, WorkPastItsTimeIsKilled) {
  const auto start = std::chrono::steady_clock::now();
  SandboxLimits limits;
  limits.seconds = 0.3;
  const SandboxResult r = run_sandboxed([] {
    for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return std::string();
  }, limits);
  EXPECT_EQ(r.status, SandboxResult::Status::TimedOut);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(Sandbox, WorkThatAllocatesWithoutEndRunsOutOfMemory) {
  SandboxLimits limits;
  limits.bytes = 64u << 20;
  const SandboxResult r = run_sandboxed([] {
    std::vector<std::vector<char>> blocks;
    for (;;) blocks.emplace_back(1u << 20, 'x');
    return std::string();
  }, limits);
  EXPECT_EQ(r.status, SandboxResult::Status::OutOfMemory);
}

TEST(Sandbox, ACrashIsReportedWithItsSignal) {
  const SandboxResult r = run_sandboxed([] {
    raise(SIGSEGV);
    return std::string("not reached");
  });
  EXPECT_EQ(r.status, SandboxResult::Status::Crashed);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_EQ(r.output, "");
}

}  // namespace
}  // namespace rm
