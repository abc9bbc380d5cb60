// Sandbox: runs a piece of work in a child process with a time and a memory
// limit, so that input which makes a library loop, allocate without end or
// crash costs the caller an error, not its life. glslang has no bound of its
// own on macro expansion: "#define A x+x" doubled 25 times takes minutes and
// gigabytes.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

namespace rm {

struct SandboxLimits {
  double seconds = 5.0;                 // wall-clock time
  std::uintmax_t bytes = 512ull << 20;  // resident memory the work may add
  // A socket to whoever waits for the result, or -1. When its other end
  // closes, no one is left to read the result, and the child is killed at
  // once, not when its time is up.
  int requester = -1;
};

struct SandboxResult {
  enum class Status { Ok, TimedOut, OutOfMemory, Crashed, Abandoned };
  Status status = Status::Ok;
  std::string output;  // what the work returned (Ok only)
  int signal = 0;      // the signal that ended it (Crashed)
};

// Runs work() in a child made by fork(), into which only the calling thread
// is copied: the work must not touch GL or other threads' state. What it
// returns comes back over a pipe. A child past its time or its memory, or
// whose requester hung up, is killed.
SandboxResult run_sandboxed(const std::function<std::string()>& work, const SandboxLimits& limits = {});

}  // namespace rm
