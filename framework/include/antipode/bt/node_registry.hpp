#pragma once
/// @file
/// NodeManifest (what a node type declares) and NodeRegistry (the node types a loader knows).
///
/// Plugins register node types through `void register_node(bt::NodeRegistry&)` (see
/// plugin/abi.hpp), typically with `registry.register_node<MyNode>()`.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/converters.hpp"
#include "antipode/bt/node.hpp"
#include "antipode/bt/ports.hpp"
#include "antipode/bt/status.hpp"

namespace antipode::bt {

/// A node type: its name in the YAML, its category, ports and children, and how to make it.
struct NodeManifest {
  std::string type;  ///< the YAML key, e.g. "SampleHands"
  NodeCategory category = NodeCategory::kAction;
  std::vector<PortInfo> ports;
  int min_children = 0;  ///< control nodes: fewest children; decorators: 1; leaves: 0
  int max_children = 0;  ///< control nodes: most children, -1 = unbounded
  std::string summary;   ///< one line for docs and `antipode nodes`
  /// Makes an instance; register_node<T>() fills it with `std::make_unique<T>(config)`.
  std::function<std::unique_ptr<Node>(const NodeConfig&)> create;

  /// The port called `name`, or null.
  const PortInfo* port(const std::string& name) const;
};

class NodeRegistry {
 public:
  NodeRegistry() = default;

  /// Registers node type T: T has `static NodeManifest manifest()` and a constructor
  /// `T(const NodeConfig&)`.
  template <typename T>
  void register_node() {
    NodeManifest manifest = T::manifest();
    if (!manifest.create) {
      manifest.create = [](const NodeConfig& config) -> std::unique_ptr<Node> {
        return std::make_unique<T>(config);
      };
    }
    add(std::move(manifest));
  }

  /// Adds a node type. Throws Error for an empty or already registered type name, a missing
  /// `create`, duplicate port names, or children bounds that do not fit the category
  /// (leaves: 0; decorators: exactly 1; control: 0 <= min <= max or max = -1). Category
  /// kSubTree is reserved for the built-in SubTree.
  void add(NodeManifest manifest);

  bool has(const std::string& type) const { return manifests_.count(type) != 0; }

  /// The manifest of `type`; throws Error "unknown node 'x' (did you mean 'y'?)".
  const NodeManifest& get(const std::string& type) const;

  /// Makes this registry and every tree with a node of `type` hold `owner` (the plugin
  /// library the type's code lives in), so the code stays loaded while it can run.
  void keep_loaded(const std::string& type, std::shared_ptr<const void> owner);

  /// Every registered type name, sorted.
  std::vector<std::string> types() const;

  /// The literal converters used by trees loaded with this registry; a plugin adds its port
  /// types here so that they accept YAML literals.
  LiteralConverters& converters() { return converters_; }
  const LiteralConverters& converters() const { return converters_; }

 private:
  std::map<std::string, NodeManifest> manifests_;
  LiteralConverters converters_;
};

/// Registers the built-in node types (docs/trees.md lists them) in `registry`.
void register_builtin_nodes(NodeRegistry& registry);

/// A registry holding the built-in node types.
NodeRegistry builtin_node_registry();

/// Same as builtin_node_registry().
inline NodeRegistry with_builtin_nodes() { return builtin_node_registry(); }

}  // namespace antipode::bt
