// The process's address-space limit (ulimit -v, RLIMIT_AS). Under one, a
// library that cannot be mapped or a thread that cannot start is reported
// by its loader in words that do not name the limit; the host's messages do.
// Mesa's compiler and llvmpipe do not check their allocations: where they
// run out, the process crashes. So the host spends less of the limit on
// its own reservations, and asks for room before the driver builds.
#pragma once

#include <cstdint>
#include <new>
#include <optional>
#include <string>
#include <utility>

namespace rm {

// The limit in KiB, as ulimit -v gives it, or nothing when there is none.
std::optional<std::uint64_t> address_space_limit_kib();

// " within this process's address-space limit (ulimit -v N KiB)", or "".
std::string within_address_space_limit();

// Under a limit, malloc keeps one arena for all threads. glibc reserves 64
// MiB of address space for each thread's arena (5 to 7 in a window), which
// left the driver too little under a limit of 1 GB; with none, arenas stay.
// Called first thing in main(), before any thread starts.
void fit_malloc_to_address_space_limit();

// The driver builds a program without the room for it: thrown by
// require_room_for_driver, caught where std::bad_alloc is.
class NoRoomForDriver : public std::bad_alloc {
 public:
  explicit NoRoomForDriver(std::string message) : message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

// About what Mesa's compiler and llvmpipe's code generation map while they
// build and first draw the largest examples (gallery: about 60 MiB), with a
// margin for heavier shaders.
constexpr std::uint64_t kDriverRoomBytes = std::uint64_t{128} << 20;

// Whether the address space left unmapped under the limit, if there is
// one, holds kDriverRoomBytes.
bool room_for_driver();

// Throws NoRoomForDriver without room_for_driver(), saying how much is left.
void require_room_for_driver();

}  // namespace rm
