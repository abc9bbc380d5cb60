// The glslang worker's work: glslang's parser, its semantic checks and its
// preprocessor over a shader's final text, each run in a sandboxed child
// (glslang_worker/sandbox) within the limits in glslang_worker/protocol.h.
#pragma once
#include <optional>

#include "glslang_worker/protocol.h"

namespace rm {

// Call glslang::InitializeProcess() first, once. `requester` is the socket
// the request came on: nullopt when its other end closed before the work was
// done (the host exited), so that no one is left to answer.
std::optional<GlslangReply> serve(const GlslangRequest& request, int requester);

}  // namespace rm
