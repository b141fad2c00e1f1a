#include "plugin_files.hpp"

#include <algorithm>

#include "antipode/plugin/plugin_host.hpp"

namespace antipode {

bool is_plugin_file_name(const std::string& path) {
  const std::filesystem::path file(path);
  return file.filename().string().rfind("libantipode_", 0) == 0 && file.extension() == ".so";
}

}  // namespace antipode

namespace antipode::detail {
namespace fs = std::filesystem;

std::vector<fs::path> plugin_files_in(const std::string& directory) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    if (is_plugin_file_name(it->path().string())) files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace antipode::detail
