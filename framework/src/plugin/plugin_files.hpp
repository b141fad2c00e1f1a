#pragma once
// The plugin files of a directory: `libantipode_*.so`, sorted by name so that loading order
// is reproducible. A directory that cannot be read holds none.

#include <filesystem>
#include <string>
#include <vector>

namespace antipode::detail {

bool is_plugin_file(const std::filesystem::path& path);

std::vector<std::filesystem::path> plugin_files_in(const std::string& directory);

}  // namespace antipode::detail
