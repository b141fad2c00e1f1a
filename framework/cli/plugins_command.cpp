#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "antipode/evaluation/exit_codes.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/plugin/abi.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "antipode/plugin/plugin_index.hpp"
#include "commands.hpp"

namespace antipode::cli {

int plugins_command() {
  PluginHost host;
  host.load_search_path();
  std::cout << "search path (ANTIPODE_PLUGIN_PATH, then build tree, then installed):\n";
  for (const auto& directory : host.search_path()) std::cout << "  " << directory << "\n";
  if (host.records().empty()) std::cout << "no plugin libraries found\n";
  for (const auto& record : host.records()) {
    std::cout << to_string(record.state) << "  " << record.path << "\n";
    if (record.state == PluginRecord::State::kLoaded) {
      std::cout << "    " << record.name << " " << record.version << "\n";
      for (const auto& offer : record.offers) std::cout << "    provides " << offer << "\n";
    } else {
      std::cout << "    " << record.reason << "\n";
    }
  }
  return kExitSuccess;
}

int check_plugin_command(const std::string& library) {
  PluginHost host(std::vector<std::string>{});
  // A path, never a name for dlopen to look up on the system's library path.
  const PluginRecord& record = host.load_library(std::filesystem::absolute(library).string());
  if (record.state != PluginRecord::State::kLoaded) {
    std::cerr << "antipode: error: " << library << ": cannot be loaded: " << record.reason << "\n";
    return kExitInvalidInput;
  }
  std::cout << library << ": loads\n"
            << "  " << record.name << " " << record.version << ", plugin ABI " << record.abi
            << " (this antipode: " << kAbiMajor << "." << kAbiMinor << ")\n";
  for (const auto& offer : record.offers) std::cout << "  provides " << offer << "\n";
  if (!is_plugin_file_name(library))
    std::cout << "  note: a plugin directory loads only files named libantipode_NAME.so; "
                 "this one would be skipped there: rename it to libantipode_"
              << record.name << ".so\n";
  return kExitSuccess;
}

int write_index_command(const std::string& directory) {
  const std::size_t count = write_plugin_index(directory);
  std::cout << directory << "/" << kPluginIndexFile << ": " << count << " plugin "
            << (count == 1 ? "library" : "libraries") << "\n";
  return kExitSuccess;
}

}  // namespace antipode::cli
