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

// A program's helper: <prefix>/`installed` when this program is installed
// and that file is there, else `built`, the one built beside this program.
inline std::filesystem::path installed_or_built(const std::filesystem::path& installed,
                                                const std::filesystem::path& built) {
  std::error_code ec;
  if (const std::filesystem::path prefix = install_prefix(); !prefix.empty())
    if (std::filesystem::exists(prefix / installed, ec)) return prefix / installed;
  return built;
}

std::filesystem::path data_dir();
inline std::filesystem::path shaderlib_dir() { return data_dir() / "shaderlib"; }
inline std::filesystem::path default_scene() { return data_dir() / "examples" / "default.frag"; }

}  // namespace rm
