// What the host and its glslang worker (raymarching-glslang) say to each
// other over the socket between them: one request, then one reply, each a
// list of byte strings. Both ends are built from the same source, so the
// strings carry native-endian lengths and nothing else.
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace rm {

// What glslang may spend on one shader: the worker runs each request in a
// child of its own (glslang_worker/sandbox), on a stack of its own, and past
// these it is an error.
constexpr double kValidationSeconds = 5.0;
constexpr std::uintmax_t kValidationBytes = std::uintmax_t{512} << 20;
constexpr size_t kValidationStack = size_t{256} << 20;
// The deepest chain of operations through variables and calls that
// validation lets through (glslang_worker/tree_checks.cpp, ChainDepth): the
// GL driver builds trees that deep. The examples reach 100 to 600.
constexpr int kMaxChainDepth = 5000;

struct GlslangRequest {
  enum class Kind { Validate, Preprocess };
  Kind kind = Kind::Validate;
  // Validate: glslang's parser and checks over `text`, after the built-ins
  // of `version_line` (which the worker builds once and keeps); with
  // `active_text`, also that text after the preprocessor.
  // Preprocess: `text` after glslang's preprocessor alone.
  std::string version_line;
  std::string text;
  std::optional<std::string> active_text;
};

struct GlslangReply {
  enum class Status { Ok, TimedOut, OutOfMemory, Crashed, NoWorker };  // NoWorker last: read_reply checks
  Status status = Status::Ok;
  int signal = 0;  // the signal that ended the work (Crashed)
  // Ok: the work's result. Validate: "DEPTH LINE CHAIN LINE\n" (the tree's
  // deepest level and the deepest chain of values through variables and
  // calls, each with its final source line; 0 0 0 0 when it did not parse),
  // glslang's log, then with active_text a NUL and that text preprocessed.
  // Preprocess: "+" and the text, or "-" and glslang's log.
  // NoWorker: why the worker could not answer.
  std::string output;
};

using ReplyDeadline = std::optional<std::chrono::steady_clock::time_point>;

// Each false or nullopt when the other end is gone, or the deadline passed.
bool write_request(int fd, const GlslangRequest& request);
std::optional<GlslangRequest> read_request(int fd);
bool write_reply(int fd, const GlslangReply& reply);
std::optional<GlslangReply> read_reply(int fd, ReplyDeadline deadline);

}  // namespace rm
