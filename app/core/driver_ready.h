// Whether the current context can finish a draw at all. Mesa's llvmpipe
// draws on one thread per CPU; when it cannot start them all (near an
// address-space limit, out of threads) it goes on without them, and its
// first glFinish then waits for them for ever: a render under Slurm would
// sit until its time limit. A 1x1 clear waited on with a time limit turns
// that hang into a message, whatever the driver.
#pragma once

#include <optional>
#include <string>

namespace rm {

// Why the current context cannot draw, or nothing when it can.
std::optional<std::string> driver_cannot_draw();

}  // namespace rm
