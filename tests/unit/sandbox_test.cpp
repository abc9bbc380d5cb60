// The sandbox that glslang runs in: what the work returns comes back whole,
// and work that runs too long, allocates too much or crashes is reported as
// such while the caller lives on; work whose requester hung up is ended.
#include "glslang_worker/sandbox.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

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

TEST(Sandbox, WorkWhoseRequesterHangsUpIsKilledAtOnce) {
  int ends[2];
  ASSERT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, ends), 0);
  SandboxLimits limits;
  limits.seconds = 30.0;
  limits.requester = ends[0];
  // The requester is a process of its own, as the host is: the sandbox's
  // child, a fork of this process, must not hold its end of the socket.
  // The clock starts before the fork: the requester may sleep before this
  // process runs again, and its 200 ms must fall inside what is timed.
  const auto start = std::chrono::steady_clock::now();
  const pid_t requester = fork();
  if (requester == 0) {
    close(ends[0]);
    const char byte = 'r';  // a requester that writes is still there
    if (write(ends[1], &byte, 1) != 1) _exit(1);
    usleep(200 * 1000);
    _exit(0);
  }
  ASSERT_GT(requester, 0);
  close(ends[1]);
  const SandboxResult r = run_sandboxed([] {
    for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return std::string();
  }, limits);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int status = 0;
  waitpid(requester, &status, 0);
  close(ends[0]);
  EXPECT_EQ(r.status, SandboxResult::Status::Abandoned);
  EXPECT_GE(seconds, 0.2);
  EXPECT_LT(seconds, 2.0);
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
