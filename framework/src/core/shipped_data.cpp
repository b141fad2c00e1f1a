#include "antipode/core/shipped_data.hpp"

#include <filesystem>

#include "antipode/config.hpp"
#include "library_dir.hpp"

namespace antipode {
namespace fs = std::filesystem;

std::string shipped_data_dir() {
  std::error_code error;
  const fs::path library = detail::library_dir();
  if (!library.empty()) {
    const fs::path installed = (library / ANTIPODE_DATA_DIR_FROM_LIBRARY).lexically_normal();
    if (fs::is_directory(installed / "trees", error)) return installed.string();
  }
  if (fs::is_directory(fs::path(ANTIPODE_SOURCE_DIR) / "trees", error)) return ANTIPODE_SOURCE_DIR;
  return {};
}

std::string resolve_shipped(const std::string& path) {
  std::error_code error;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path, error)) return path;
  const std::string dir = shipped_data_dir();
  if (dir.empty()) return path;
  const fs::path shipped = fs::path(dir) / path;
  return fs::exists(shipped, error) ? shipped.string() : path;
}

}  // namespace antipode
