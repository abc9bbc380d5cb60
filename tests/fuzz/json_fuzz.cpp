// libFuzzer target for Shadertoy's JSON export (core/shadertoy_json), as
// `import` and a run from a .json read it. The input is the JSON text. A text
// it reads becomes a project, and each of its shader files is then
// preprocessed from memory, which reads the #pragma channelN lines the reader
// wrote. Checked: no crash or hang; a refused text says where, in one line
// ("LINE:COL: why"); a project has an image pass, and `import` writes only
// files the project holds, or common.glsl.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/channel_spec.h"
#include "core/shadertoy_json.h"
#include "core/source.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rm::Diagnostic error;
  const auto project = rm::read_shadertoy_json(text, "/fuzz/media", &error);
  if (!project) {
    if (error.message.empty() || error.message.find('\n') != std::string::npos || error.line < 1 || error.column < 1)
      std::abort();
    return 0;
  }
  if (!project->files.count(rm::ShadertoyProject::kImage)) std::abort();
  const auto imported = project->files_to_import();
  for (const auto& [name, file_text] : imported)
    if (!project->files.count(name) && name != rm::ShadertoyProject::kCommon) std::abort();

  const std::string root = "/fuzz/project.json/";
  rm::FileSystem memory;
  memory.read = [&](const std::filesystem::path& path, rm::Diagnostic* why) -> std::optional<std::string> {
    const std::string key = path.lexically_normal().string();
    if (key.rfind(root, 0) == 0)
      if (auto it = project->files.find(key.substr(root.size())); it != project->files.end()) return it->second;
    why->message = "no such file";
    return std::nullopt;
  };
  memory.exists = [&](const std::filesystem::path& path) {
    const std::string key = path.lexically_normal().string();
    return key.rfind(root, 0) == 0 && project->files.count(key.substr(root.size())) > 0;
  };
  rm::SourceOptions options;
  options.shaderlib_dir = "/fuzz/shaderlib";
  options.forced_includes = {rm::ShadertoyProject::kCommon};  // as a run from the .json includes it
  for (const auto& [name, file_text] : project->files)
    if (rm::is_shader_file(name)) rm::preprocess(root + name, options, memory);
  return 0;
}
