#include "core/data_paths.h"

#include <cstdlib>

namespace rm {

std::filesystem::path data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("RAYMARCHING_DATA_DIR"); env && *env) return env;
  std::error_code ec;
  if (const fs::path prefix = install_prefix(); !prefix.empty()) {
    const fs::path installed = prefix / RM_INSTALL_DATA_SUBDIR;
    if (fs::is_directory(installed / "shaderlib", ec)) return installed;
  }
  return RM_SOURCE_DATA_DIR;
}

}  // namespace rm
