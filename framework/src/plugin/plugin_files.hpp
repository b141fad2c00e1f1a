#pragma once
// The plugin files of a directory (is_plugin_file_name, plugin_host.hpp), sorted by name so
// that loading order is reproducible. A directory that cannot be read holds none.

#include <filesystem>
#include <string>
#include <vector>

namespace antipode::detail {

std::vector<std::filesystem::path> plugin_files_in(const std::string& directory);

}  // namespace antipode::detail
