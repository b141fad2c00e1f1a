#pragma once
// Parsing and checking a tree file's YAML into a FileSpec (see tree_spec.hpp). Every check
// throws the first problem as a located antipode::Error.

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/bt/node_registry.hpp"
#include "antipode/plugin/component_source.hpp"
#include "tree_spec.hpp"

namespace antipode::bt::detail {

struct ParseContext {
  std::string file;
  const NodeRegistry* registry = nullptr;
  const ComponentSource* components = nullptr;
  const FileSpec* spec = nullptr;  // components and tree headers parsed so far
};

// Top level: keys, components, main and trees (headers, then bodies) in that order.
FileSpec parse_document(const YAML::Node& document, const ParseContext& context);

// One node written as a list item or a child: a one-key mapping {Type: value} or a bare
// scalar `Type`.
NodeSpec parse_node(const YAML::Node& item, const ParseContext& context);

// One node given its type key and value.
NodeSpec parse_node_entry(const YAML::Node& key, const YAML::Node& value,
                          const ParseContext& context);

// A SubTree node's value (tree name, `ports` remapping, `name`).
void parse_subtree_node(NodeSpec& spec, const YAML::Node& value, const ParseContext& context);

// Binds one written port value.
PortBinding bind_port(const PortInfo& info, const std::string& node, const YAML::Node& key,
                      const YAML::Node& value, const ParseContext& context);

// The binding of an input port the YAML did not give (its default).
PortBinding default_binding(const PortInfo& info, const SourceLocation& node_where,
                            const LiteralConverters& converters);

// Throws for a repeated or non-scalar key in `map`.
void check_keys(const YAML::Node& map, const std::string& file);

// " (are the ports of X indented under it?)" when `second` looks like a port of `first`.
std::string indentation_hint(const std::string& first, const std::string& second);

// The names of `map`'s keys.
std::vector<std::string> key_names(const YAML::Node& map);

}  // namespace antipode::bt::detail
