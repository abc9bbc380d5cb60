#include "core/glslviewer_passes.h"

#include <array>
#include <utility>

#include "core/lexing.h"

namespace rm {

namespace {

constexpr char kSeparator = '#';  // no define holds one, and a file name rarely does
constexpr std::string_view kScene = "SCENE";

// glslViewer's buffer sampler prefixes, and the names of their passes.
constexpr std::array<std::pair<std::string_view, std::string_view>, 2> kBuffers = {{
    {"u_buffer", "BUFFER_"},
    {"u_doubleBuffer", "DOUBLE_BUFFER_"},
}};

bool a_number(std::string_view text) {
  if (text.empty() || text.size() > 2) return false;  // a project has at most 16 buffers
  for (char c : text)
    if (!lexing::is_digit(c)) return false;
  return true;
}

// `text` is `prefix` and then a number.
bool numbered(std::string_view text, std::string_view prefix) {
  return text.size() > prefix.size() && text.substr(0, prefix.size()) == prefix &&
         a_number(text.substr(prefix.size()));
}

}  // namespace

std::filesystem::path glslviewer_pass(const std::filesystem::path& file, std::string_view name) {
  return file.parent_path() / (file.filename().string() + kSeparator + std::string(name));
}

std::optional<GlslViewerPass> glslviewer_pass_of(const std::filesystem::path& pass) {
  const std::string file_name = pass.filename().string();
  const size_t at = file_name.rfind(kSeparator);
  if (at == std::string::npos || at == 0) return std::nullopt;
  const std::string name = file_name.substr(at + 1);
  const std::filesystem::path file = pass.parent_path() / file_name.substr(0, at);
  if (name == kScene) return GlslViewerPass{file, name, ""};
  for (const auto& [sampler_prefix, prefix] : kBuffers)
    if (numbered(name, prefix)) return GlslViewerPass{file, name, name};
  return std::nullopt;
}

std::string glslviewer_pass_read_by(std::string_view sampler) {
  if (sampler == "u_scene") return std::string(kScene);
  for (const auto& [sampler_prefix, prefix] : kBuffers)
    if (numbered(sampler, sampler_prefix)) return std::string(prefix) + std::string(sampler.substr(sampler_prefix.size()));
  return "";
}

}  // namespace rm
