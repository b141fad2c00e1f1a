#pragma once
/// @file
/// Bounds on YAML input: a document whose aliases expand to millions of nodes ("billion
/// laughs") must be an error, not hours of work or gigabytes of memory.

#include <cstddef>
#include <string>

#include <yaml-cpp/yaml.h>

namespace antipode {

/// The most YAML nodes, aliases expanded, that a tree file, a scene file or a `--set` value
/// may hold.
inline constexpr std::size_t kMaxYamlNodes = 1'000'000;

/// Throws antipode::Error "WHAT: more than LIMIT YAML nodes once its aliases are expanded"
/// when `node` holds more; stops counting there, so the check itself stays cheap.
void check_yaml_size(const YAML::Node& node, const std::string& what,
                     std::size_t limit = kMaxYamlNodes);

}  // namespace antipode
