#include "core/address_space.h"

#include <sys/resource.h>

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

}  // namespace rm
