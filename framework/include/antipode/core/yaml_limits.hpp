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

/// The YAML map of `kind` (e.g. "gripper fields") in the file at `path`, checked as above.
/// Throws antipode::Error starting with `what` for a missing file, a path that is not a
/// regular file, YAML that does not parse, an empty file, and a document that is not a map,
/// each pointing to `examples` (the folder of such files, e.g. "robots/grippers/").
YAML::Node load_yaml_map(const std::string& path, const std::string& what, const std::string& kind,
                         const std::string& examples);

}  // namespace antipode
