// The process's address-space limit (ulimit -v, RLIMIT_AS). Under one, a
// library that cannot be mapped or a thread that cannot start is reported
// by its loader in words that do not name the limit; the host's messages do.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rm {

// The limit in KiB, as ulimit -v gives it, or nothing when there is none.
std::optional<std::uint64_t> address_space_limit_kib();

// " within this process's address-space limit (ulimit -v N KiB)", or "".
std::string within_address_space_limit();

}  // namespace rm
