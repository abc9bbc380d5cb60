// Compiler-style diagnostics: "path:line:col: error: message".
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace rm {

// Exit status of every command, as compilers use it.
// 124: a run stopped by its time limit, as timeout(1) exits.
enum ExitCode : int { kExitOk = 0, kExitShaderError = 1, kExitUsage = 2, kExitTimeout = 124 };

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string path;  // file the problem is in; empty when unknown
  int line = 0;      // 1-based; 0 when the message has no line (link errors)
  int column = 0;    // 1-based; 0 when unknown
  std::string message;
  // The host could not check the shader at all (the scene could not be read,
  // or its glslang worker would not start or answer): an error of the
  // machine, not of the shader.
  bool unchecked = false;
  bool operator==(const Diagnostic&) const = default;

  // "path:line:col" (only what is known; "raymarching" for no path).
  std::string place() const;
  // One line, in the form editors' quickfix lists parse. Control characters
  // and bytes that are not UTF-8 (glslang quotes them from the code) are
  // written as \xNN, so the line stays one line and prints cleanly.
  std::string str() const;
};

using Diagnostics = std::vector<Diagnostic>;

// The scene at `path` could not be read (`why`, the system's words): nothing
// was checked, as with a scene missing from the command line (status 2).
Diagnostic scene_unreadable(std::string path, const std::string& why);

int count_errors(const Diagnostics& diags);
// The exit status for a shader that failed to build with `diags`: 1, or 2
// where the host could not check it (an error of the machine, which a farm
// retries elsewhere, not one of the shader).
int build_failure_status(const Diagnostics& diags);
// Appends those of `more` that `to` does not hold yet: the passes that draw
// one file (glslViewer's buffers) find the same problems in the code they share.
void append_new(Diagnostics* to, const Diagnostics& more);
std::string printable(std::string_view text);  // text with \xNN for what str() escapes
std::string join(const Diagnostics& diags);  // one diagnostic per line

}  // namespace rm
