// The host's side of its glslang worker (raymarching-glslang, see
// app/glslang_worker/main.cpp): started on the first request, kept for the
// next ones, started again when it has gone away.
#pragma once
#include <string>
#include <thread>

#include "glslang_worker/protocol.h"

namespace rm {

// Sends `request` to the process's worker and waits for its reply. Safe from
// any thread; requests from several threads take turns.
GlslangReply ask_glslang(const GlslangRequest& request);

// How many requests this process has asked of its worker: each is a round
// trip (tests count those a step makes).
long glslang_requests();

// Starts the worker and has it build glslang's built-in symbols for
// `version_line`, on a thread of its own, while the caller opens its window
// or display: the first shader then waits for neither (about 50 ms). A
// request made meanwhile takes its turn after it. Joined when destroyed; a
// worker that cannot start says so at the first real request.
class GlslangWarmUp {
 public:
  explicit GlslangWarmUp(std::string version_line);
  ~GlslangWarmUp();
  GlslangWarmUp(const GlslangWarmUp&) = delete;
  GlslangWarmUp& operator=(const GlslangWarmUp&) = delete;

 private:
  std::thread thread_;
};

}  // namespace rm
