#include "core/glslviewer_buffers.h"

#include <array>
#include <utility>

#include "core/lexing.h"

namespace rm {

namespace {

constexpr char kSeparator = '#';  // no define holds one, and a file name rarely does

// glslViewer's sampler prefixes, and the defines of their passes.
constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kBuffers = {{
    {"u_buffer", "BUFFER_"},
    {"u_doubleBuffer", "DOUBLE_BUFFER_"},
}};

bool all_digits(std::string_view text) {
  if (text.empty() || text.size() > 2) return false;  // a project has at most 16 buffers
  for (char c : text)
    if (!lexing::is_digit(c)) return false;
  return true;
}

}  // namespace

std::filesystem::path glslviewer_pass(const std::filesystem::path& file, std::string_view define) {
  return file.parent_path() / (file.filename().string() + kSeparator + std::string(define));
}

std::optional<GlslViewerPass> glslviewer_pass_of(const std::filesystem::path& pass) {
  const std::string name = pass.filename().string();
  const size_t at = name.rfind(kSeparator);
  if (at == std::string::npos || at == 0) return std::nullopt;
  const std::string define = name.substr(at + 1);
  for (const auto& [prefix, define_prefix] : kBuffers)
    if (define.size() > define_prefix.size() && define.compare(0, define_prefix.size(), define_prefix) == 0 &&
        all_digits(std::string_view(define).substr(define_prefix.size())))
      return GlslViewerPass{pass.parent_path() / name.substr(0, at), define};
  return std::nullopt;
}

std::string glslviewer_buffer_define(std::string_view sampler) {
  for (const auto& [prefix, define_prefix] : kBuffers)
    if (sampler.size() > prefix.size() && sampler.substr(0, prefix.size()) == prefix &&
        all_digits(sampler.substr(prefix.size())))
      return std::string(define_prefix) + std::string(sampler.substr(prefix.size()));
  return "";
}

}  // namespace rm
