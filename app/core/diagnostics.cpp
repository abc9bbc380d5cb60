#include "core/diagnostics.h"

#include <algorithm>
#include <cstdio>

#include "core/one_line.h"

namespace rm {

namespace {

// How many continuation bytes follow a UTF-8 lead byte; -1 if it is none.
int continuation_bytes(unsigned char lead) {
  if (lead >= 0xC2 && lead <= 0xDF) return 1;
  if (lead >= 0xE0 && lead <= 0xEF) return 2;
  if (lead >= 0xF0 && lead <= 0xF4) return 3;
  return -1;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
      continue;
    }
    if (c >= 0x80) {
      const int more = continuation_bytes(c);
      bool whole = more > 0 && i + static_cast<size_t>(more) < text.size();
      for (int k = 1; whole && k <= more; ++k) whole = continues_a_character(text[i + k]);
      if (whole) {
        out.append(text.substr(i, static_cast<size_t>(more) + 1));
        i += static_cast<size_t>(more);
        continue;
      }
    }
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
    out += escaped;
  }
  return out;
}

std::string Diagnostic::place() const {
  std::string out = path.empty() ? std::string("raymarching") : printable(path);
  if (line > 0) {
    out += ':' + std::to_string(line);
    if (column > 0) out += ':' + std::to_string(column);
  }
  return out;
}

std::string Diagnostic::str() const {
  std::string out = place();
  out += severity == Severity::Error ? ": error: " : ": warning: ";
  out += printable(message);
  return out;
}

int count_errors(const Diagnostics& diags) {
  return static_cast<int>(std::count_if(diags.begin(), diags.end(), [](const Diagnostic& d) {
    return d.severity == Severity::Error;
  }));
}

Diagnostic scene_unreadable(std::string path, const std::string& why) {
  Diagnostic d;
  d.path = std::move(path);
  d.message = "cannot read scene: " + why;
  d.unchecked = true;
  return d;
}

int build_failure_status(const Diagnostics& diags) {
  const bool unchecked = std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.unchecked; });
  return unchecked ? kExitUsage : kExitShaderError;
}

void append_new(Diagnostics* to, const Diagnostics& more) {
  for (const Diagnostic& d : more)
    if (std::find(to->begin(), to->end(), d) == to->end()) to->push_back(d);
}

std::string join(const Diagnostics& diags) {
  std::string out;
  for (const auto& d : diags) out += d.str() + '\n';
  return out;
}

}  // namespace rm
