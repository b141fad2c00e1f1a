#include "antipode/bt/node_registry.hpp"

#include <set>

#include "antipode/core/error.hpp"
#include "tree_context.hpp"

namespace antipode::bt {
namespace {

void check_children(const NodeManifest& manifest) {
  const auto bad = [&](const std::string& rule) {
    throw Error("node type '" + manifest.type + "' (" + to_string(manifest.category) +
                ") must have " + rule + ", got min_children " +
                std::to_string(manifest.min_children) + " and max_children " +
                std::to_string(manifest.max_children));
  };
  switch (manifest.category) {
    case NodeCategory::kAction:
    case NodeCategory::kCondition:
      if (manifest.min_children != 0 || manifest.max_children != 0) bad("no children");
      break;
    case NodeCategory::kDecorator:
    case NodeCategory::kSubTree:
      if (manifest.min_children != 1 || manifest.max_children != 1) bad("exactly 1 child");
      break;
    case NodeCategory::kControl:
      if (manifest.min_children < 0 ||
          (manifest.max_children != -1 && manifest.max_children < manifest.min_children)) {
        bad("0 <= min_children <= max_children (or max_children -1)");
      }
      break;
  }
}

void check_ports(const NodeManifest& manifest) {
  std::set<std::string> names;
  for (const auto& port : manifest.ports) {
    if (port.name.empty()) throw Error("node type '" + manifest.type + "' has a nameless port");
    const bool has_children = manifest.category == NodeCategory::kControl ||
                              manifest.category == NodeCategory::kDecorator;
    if (port.name == "name" ||
        (has_children && (port.name == "child" || port.name == "children"))) {
      throw Error("node type '" + manifest.type + "' may not call a port '" + port.name +
                  "': the YAML grammar reserves that key");
    }
    if (!names.insert(port.name).second) {
      throw Error("node type '" + manifest.type + "' declares port '" + port.name + "' twice");
    }
  }
}

}  // namespace

const PortInfo* NodeManifest::port(const std::string& name) const {
  for (const auto& info : ports) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

void NodeRegistry::add(NodeManifest manifest) {
  if (manifest.type.empty()) throw Error("a node type needs a name");
  if (has(manifest.type)) throw Error("node type '" + manifest.type + "' is already registered");
  if (!manifest.create) throw Error("node type '" + manifest.type + "' has no create function");
  if (manifest.category == NodeCategory::kSubTree && manifest.type != "SubTree") {
    throw Error("node type '" + manifest.type + "': category subtree is reserved for SubTree");
  }
  check_children(manifest);
  check_ports(manifest);
  const std::string type = manifest.type;
  manifests_.emplace(type, std::move(manifest));
}

const NodeManifest& NodeRegistry::get(const std::string& type) const {
  const auto found = manifests_.find(type);
  if (found == manifests_.end()) {
    throw UnknownTypeError("unknown node '" + type + "'" + did_you_mean(type, types()));
  }
  return found->second;
}

void NodeRegistry::keep_loaded(const std::string& type, std::shared_ptr<const void> owner) {
  const auto found = manifests_.find(type);
  if (found == manifests_.end()) throw Error("unknown node '" + type + "'");
  auto& create = found->second.create;
  create = [make = std::move(create), owner = std::move(owner)](const NodeConfig& config) {
    if (config.context) config.context->libraries.push_back(owner);
    return make(config);
  };
}

std::vector<std::string> NodeRegistry::types() const {
  std::vector<std::string> names;
  names.reserve(manifests_.size());
  for (const auto& [name, manifest] : manifests_) names.push_back(name);
  return names;
}

}  // namespace antipode::bt
