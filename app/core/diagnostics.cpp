#include "core/diagnostics.h"

#include <algorithm>

namespace rm {

std::string Diagnostic::str() const {
  std::string out = path.empty() ? std::string("raymarching") : path;
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (column > 0) out += ':' + std::to_string(column);
  }
  out += severity == Severity::Error ? ": error: " : ": warning: ";
  out += message;
  return out;
}

int count_errors(const Diagnostics& diags) {
  return static_cast<int>(std::count_if(diags.begin(), diags.end(), [](const Diagnostic& d) {
    return d.severity == Severity::Error;
  }));
}

std::string join(const Diagnostics& diags) {
  std::string out;
  for (const auto& d : diags) out += d.str() + '\n';
  return out;
}

}  // namespace rm
