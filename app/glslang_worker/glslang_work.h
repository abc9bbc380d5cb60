// The glslang worker's work: glslang's parser, its semantic checks and its
// preprocessor over a shader's final text, each run in a sandboxed child
// (glslang_worker/sandbox) within the limits in glslang_worker/protocol.h.
#pragma once
#include "glslang_worker/protocol.h"

namespace rm {

// Call glslang::InitializeProcess() first, once.
GlslangReply serve(const GlslangRequest& request);

}  // namespace rm
