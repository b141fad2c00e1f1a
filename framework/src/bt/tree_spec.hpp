#pragma once
// The validated form of a tree file: what the parser produces and the builder instantiates.

#include <any>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/bt/node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/core/error.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode::bt::detail {

// One `ports:` entry of a SubTree node: subtree port <- parent entry or literal.
struct RemapSpec {
  std::string port;  // the subtree's port (its blackboard key)
  PortDirection direction = PortDirection::kInput;
  std::optional<std::string> parent_key;  // set: connected to this entry of the parent
  YAML::Node literal;                     // otherwise: the literal as written
  std::any value;                         // ...converted by the type check
  SourceLocation key_where;
  SourceLocation where;
};

struct NodeSpec {
  const NodeManifest* manifest = nullptr;
  std::string type;
  std::string name;  // the YAML `name:` ("" when not given)
  SourceLocation where;
  std::map<std::string, PortBinding> ports;  // every declared port, bound
  std::vector<NodeSpec> children;
  // SubTree only.
  std::string subtree;
  SourceLocation subtree_where;
  std::vector<RemapSpec> remaps;
};

struct TreePortSpec {
  std::string name;
  PortDirection direction = PortDirection::kInput;
  SourceLocation where;
};

struct TreeSpec {
  std::string name;
  SourceLocation where;
  std::vector<TreePortSpec> ports;
  YAML::Node root_key;  // the root node's key and value, parsed after all headers
  YAML::Node root_value;
  NodeSpec root;

  const TreePortSpec* port(const std::string& port_name) const {
    for (const auto& declared : ports) {
      if (declared.name == port_name) return &declared;
    }
    return nullptr;
  }
};

struct ComponentSpec {
  std::string name;
  std::string plugin;
  ComponentKind kind = ComponentKind::kSampler;
  SourceLocation where;
  YAML::Node params;  // the component's mapping, `plugin` included
};

struct FileSpec {
  std::string file;
  std::vector<ComponentSpec> components;
  std::string main;
  std::vector<TreeSpec> trees;  // in file order

  const TreeSpec* tree(const std::string& name) const {
    for (const auto& spec : trees) {
      if (spec.name == name) return &spec;
    }
    return nullptr;
  }
  const ComponentSpec* component(const std::string& name) const {
    for (const auto& spec : components) {
      if (spec.name == name) return &spec;
    }
    return nullptr;
  }
};

}  // namespace antipode::bt::detail
