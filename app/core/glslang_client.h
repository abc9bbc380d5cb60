// The host's side of its glslang worker (raymarching-glslang, see
// app/glslang_worker/main.cpp): started on the first request, kept for the
// next ones, started again when it has gone away.
#pragma once
#include "glslang_worker/protocol.h"

namespace rm {

// Sends `request` to the process's worker and waits for its reply. Safe from
// any thread; requests from several threads take turns.
GlslangReply ask_glslang(const GlslangRequest& request);

}  // namespace rm
