// Shadertoy's JSON export ({"Shader": {"info", "renderpass": [...]}}, the
// shape shadertoy.com's API returns) read into the files of a raymarching
// project: image.frag, buffer_a.frag ... buffer_d.frag, cube_a.frag and common.glsl, each
// pass naming its inputs with #pragma channelN (core/channel_spec.h). The
// same files run straight from the JSON (an in-memory tree under
// PROJECT.json/) and are what `import` writes for editing with hot reload.
#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/source.h"

namespace rm {

struct ShadertoyProject {
  std::string name;                           // info.name, or ""
  // File name -> text, as a run from the JSON reads them: common.glsl is
  // always there (empty without a Common pass) and comes into every pass
  // as a forced include, so each pass is its JSON code, line for line,
  // followed by its #pragma channelN lines.
  std::map<std::string, std::string> files;
  bool has_common = false;
  std::vector<std::string> warnings;          // one line each: what runs with a stand-in or not at all
  static constexpr const char* kImage = "image.frag";
  static constexpr const char* kCommon = "common.glsl";

  // The files `import` writes: each pass includes common.glsl on its first
  // line, and there is no common.glsl without a Common pass.
  std::map<std::string, std::string> files_to_import() const;

  // The warnings as diagnostics at the JSON, the form a build prints them in.
  Diagnostics warnings_at(const std::filesystem::path& json) const;
};

// Reads the JSON text. Media that only shadertoy.com serves (/media/a/NAME)
// is looked up by file name in `media_dir`; a missing one is replaced by a
// stand-in and warned about. nullopt with *error (its line, column and
// message; no path) on JSON that does not parse or holds no image pass.
std::optional<ShadertoyProject> read_shadertoy_json(const std::string& text, const std::filesystem::path& media_dir,
                                                    Diagnostic* error);

// Reads a .json file from disk (a regular file, within the shader size
// limit); nullopt with *error ("PATH:LINE:COL: why", or the read's error).
std::optional<ShadertoyProject> read_shadertoy_file(const std::filesystem::path& json,
                                                    const std::filesystem::path& media_dir, std::string* error);

bool is_shadertoy_json(const std::filesystem::path& path);

// Whether `pass` is a stand-in the host made for missing media (value noise
// for a texture, a sky for a cube map). Media exist before any pass draws,
// so a stand-in is drawn before the buffers that read it.
bool is_media_stand_in(const std::filesystem::path& pass);

// Files under `json`/ come from the JSON file, read again on every call so a
// save of the JSON reloads (and parsed again only when its text changed);
// everything else comes from the disk.
FileSystem shadertoy_file_system(const std::filesystem::path& json, const std::filesystem::path& media_dir);

}  // namespace rm
