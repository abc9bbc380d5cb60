#include "core/address_space.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

namespace rm {

std::optional<std::uint64_t> address_space_limit_kib() {
  struct rlimit space {};
  if (getrlimit(RLIMIT_AS, &space) != 0 || space.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return space.rlim_cur / 1024;
}

std::string within_address_space_limit() {
  const auto kib = address_space_limit_kib();
  return kib ? " within this process's address-space limit (ulimit -v " + std::to_string(*kib) + " KiB)" : "";
}

void fit_malloc_to_address_space_limit() {
  if (address_space_limit_kib()) mallopt(M_ARENA_MAX, 1);
}

namespace {

// The bytes mapped now (VmSize): the first field of /proc/self/statm, in pages.
std::optional<std::uint64_t> mapped_bytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) return std::nullopt;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// The bytes left under the limit, or nothing without one.
std::optional<std::uint64_t> address_space_left() {
  const auto kib = address_space_limit_kib();
  if (!kib) return std::nullopt;
  const auto mapped = mapped_bytes();
  if (!mapped) return std::nullopt;
  const std::uint64_t limit = *kib << 10;
  return limit > *mapped ? limit - *mapped : 0;
}

}  // namespace

bool room_for_driver() {
  const auto left = address_space_left();
  return !left || *left >= kDriverRoomBytes;
}

void require_room_for_driver() {
  const auto left = address_space_left();
  if (!left || *left >= kDriverRoomBytes) return;
  throw NoRoomForDriver("not enough memory to build the shader: " + std::to_string(*left >> 20) +
                        " MiB of address space left" + within_address_space_limit() + ", and the driver needs about " +
                        std::to_string(kDriverRoomBytes >> 20) + " MiB");
}

}  // namespace rm
