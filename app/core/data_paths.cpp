#include "core/data_paths.h"

#include <cstdlib>
#include <system_error>

namespace rm {

std::filesystem::path data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("RAYMARCHING_DATA_DIR"); env && *env) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / RM_INSTALL_DATA_SUBDIR;
    if (fs::is_directory(installed / "shaderlib", ec)) return installed;
  }
  return RM_SOURCE_DATA_DIR;
}

}  // namespace rm
