#include "antipode/core/error.hpp"
#include "commands.hpp"

namespace antipode::cli {

std::vector<std::pair<std::string, std::string>> parse_overrides(
    const std::vector<std::string>& entries) {
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const auto& entry : entries) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw Error("--set '" + entry + "' must have the form key=value", {},
                  "e.g. --set sampler.samples=500");
    }
    overrides.emplace_back(entry.substr(0, equals), entry.substr(equals + 1));
  }
  return overrides;
}

}  // namespace antipode::cli
