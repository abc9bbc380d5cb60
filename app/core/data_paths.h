// Where the bundled shaderlib and examples live: beside an install
// (<prefix>/share/raymarching), else in the source tree this was built from.
// RAYMARCHING_DATA_DIR overrides both.
#pragma once
#include <filesystem>
#include <system_error>

namespace rm {

// The prefix this program runs from if it is installed (<prefix>/bin/): its
// folder's parent; empty when /proc cannot say.
inline std::filesystem::path install_prefix() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path().parent_path();
}

std::filesystem::path data_dir();
inline std::filesystem::path shaderlib_dir() { return data_dir() / "shaderlib"; }
inline std::filesystem::path default_scene() { return data_dir() / "examples" / "default.frag"; }

}  // namespace rm
