// Compiler-style diagnostics: "path:line:col: error: message".
#pragma once
#include <string>
#include <vector>

namespace rm {

// Exit status of every command, as compilers use it.
enum ExitCode : int { kExitOk = 0, kExitShaderError = 1, kExitUsage = 2 };

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string path;  // file the problem is in; empty when unknown
  int line = 0;      // 1-based; 0 when the message has no line (link errors)
  int column = 0;    // 1-based; 0 when unknown
  std::string message;

  std::string str() const;  // one line, in the form editors' quickfix lists parse
};

using Diagnostics = std::vector<Diagnostic>;

int count_errors(const Diagnostics& diags);
std::string join(const Diagnostics& diags);  // one diagnostic per line

}  // namespace rm
