// Under an address-space limit (ulimit -v), the host spends less of it on
// its own stacks, and refuses to let the driver build where the room left
// is too small for Mesa's compiler, which would crash where it runs out.
// Each case sets the limit in a child process of its own.
#include "core/address_space.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <string>

#include "core/deep_stack.h"

namespace rm {
namespace {

// `check`'s exit status, run in a child under `ulimit -v kib`.
int under_limit(std::uint64_t kib, const std::function<int()>& check) {
  const pid_t pid = fork();
  if (pid == 0) {
    const rlimit limit{kib << 10, kib << 10};
    _exit(setrlimit(RLIMIT_AS, &limit) == 0 ? check() : 100);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::uint64_t mapped_kib() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)) >> 10;
}

TEST(AddressSpace, ADeepStackIsASixteenthOfTheLimitBetweenEightAnd256MiB) {
  if (!address_space_limit_kib()) EXPECT_EQ(deep_stack_bytes(), kDeepStack);
  auto stack_is = [](std::uint64_t kib, size_t bytes) {
    return under_limit(kib, [&] { return deep_stack_bytes() == bytes ? 0 : 1; });
  };
  EXPECT_EQ(stack_is(1u << 20, size_t{64} << 20), 0);  // 1 GiB
  EXPECT_EQ(stack_is(100u << 10, size_t{8} << 20), 0);
  EXPECT_EQ(stack_is(std::uint64_t{16} << 20, kDeepStack), 0);  // 16 GiB
}

TEST(AddressSpace, TheDriverBuildsOnlyWithRoomForIt) {
  EXPECT_NO_THROW(require_room_for_driver());
  const std::uint64_t mapped = mapped_kib();
  auto refused = [](std::string* message) {
    try {
      require_room_for_driver();
    } catch (const NoRoomForDriver& e) {
      *message = e.what();
      return true;
    }
    return false;
  };
  // Room for it: a gigabyte beyond what is mapped.
  EXPECT_EQ(under_limit(mapped + (1u << 20), [&] {
              std::string message;
              return refused(&message) ? 1 : 0;
            }),
            0);
  // Too little: 64 MiB beyond. The message says how much is left, and the limit.
  const std::uint64_t limit = mapped + (64u << 10);
  EXPECT_EQ(under_limit(limit, [&] {
              std::string message;
              if (!refused(&message)) return 1;
              const std::string left = "not enough memory to build the shader: ";
              const std::string within = " MiB of address space left within this process's address-space limit "
                                         "(ulimit -v " + std::to_string(limit) + " KiB), and the driver needs about 128 MiB";
              const bool ok = message.rfind(left, 0) == 0 && message.size() > left.size() + within.size() &&
                              message.compare(message.size() - within.size(), within.size(), within) == 0;
              return ok ? 0 : 2;
            }),
            0);
}

}  // namespace
}  // namespace rm
