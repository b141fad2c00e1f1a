#include "plugin_files.hpp"

#include <algorithm>

namespace antipode::detail {
namespace fs = std::filesystem;

bool is_plugin_file(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.rfind("libantipode_", 0) == 0 && path.extension() == ".so";
}

std::vector<fs::path> plugin_files_in(const std::string& directory) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    if (is_plugin_file(it->path())) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace antipode::detail
