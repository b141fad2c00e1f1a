#include <iostream>

#include "commands.hpp"
#include "exit_codes.hpp"
#include "session.hpp"

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

}  // namespace antipode::cli
