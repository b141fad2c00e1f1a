#pragma once
// `--set` overrides (LoadOptions::overrides).

#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace antipode::bt::detail {

using Overrides = std::vector<std::pair<std::string, std::string>>;

// Applies the "component.param[.sub]=value" overrides to `document` (values read as YAML)
// and returns the plain "key=value" ones, which become string entries of the main tree.
// Throws Error for an unknown component or an invalid entry name.
Overrides apply_overrides(YAML::Node& document, const Overrides& overrides);

}  // namespace antipode::bt::detail
