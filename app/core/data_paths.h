// Where the bundled shaderlib and examples live: beside an install
// (<prefix>/share/raymarching), else in the source tree this was built from.
// RAYMARCHING_DATA_DIR overrides both.
#pragma once
#include <filesystem>

namespace rm {

std::filesystem::path data_dir();
inline std::filesystem::path shaderlib_dir() { return data_dir() / "shaderlib"; }
inline std::filesystem::path default_scene() { return data_dir() / "examples" / "default.frag"; }

}  // namespace rm
