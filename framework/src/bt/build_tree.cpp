#include <map>

#include "build_tree.hpp"

#include "checks.hpp"
#include "tree_context.hpp"

namespace antipode::bt::detail {
namespace {

// Rethrows an error without a location as one located at `where`, prefixed with `who`.
[[noreturn]] void relocate(const std::string& who, const SourceLocation& where) {
  rethrow_with_context(who, where);
}

}  // namespace

void TreeBuilder::create_components() {
  for (const auto& declared : spec.components) {
    const std::string owner = "component '" + declared.name + "'";
    Parameters params(declared.params, owner, spec.file);
    params.require<std::string>("plugin");  // known to the loader, not to the factory
    std::shared_ptr<Component> made;
    try {
      made = components->create(declared.plugin, params);
    } catch (...) {
      relocate(owner, declared.where);
    }
    if (!made || made->kind() != declared.kind) {
      throw Error("plugin type '" + declared.plugin + "' did not make a " +
                      to_string(declared.kind) + " for " + owner,
                  declared.where);
    }
    context->components.emplace(declared.name, std::move(made));
    context->component_plugins.emplace(declared.name, declared.plugin);
  }
}

std::shared_ptr<Blackboard> TreeBuilder::subtree_blackboard(
    const NodeSpec& node, const std::shared_ptr<Blackboard>& parent) const {
  auto inner = std::make_shared<Blackboard>(converters);
  for (const auto& remap : node.remaps) {
    if (remap.parent_key) {
      inner->remap(remap.port, parent, *remap.parent_key);
    } else {
      inner->set_any(remap.port, remap.value);
    }
  }
  return inner;
}

std::unique_ptr<Node> TreeBuilder::make_node(const NodeSpec& node, const std::string& path,
                                             const std::shared_ptr<Blackboard>& blackboard) {
  NodeConfig config;
  config.type = node.type;
  config.name = !node.name.empty() ? node.name : !node.subtree.empty() ? node.subtree : node.type;
  config.path = path;
  config.where = node.where;
  config.category = node.manifest->category;
  config.ports = node.ports;
  config.blackboard = blackboard;
  config.context = context;
  std::unique_ptr<Node> made;
  try {
    made = node.manifest->create(config);
  } catch (...) {
    relocate(node.type, node.where);
  }
  if (!made) throw Error("node type '" + node.type + "' made no node", node.where);
  if (!node.subtree.empty()) {
    const TreeSpec& tree = *spec.tree(node.subtree);
    const std::string inner_path = path + "/" + tree.name + "/" + tree.root.type;
    NodeAccess::add_child(*made,
                          make_node(tree.root, inner_path, subtree_blackboard(node, blackboard)));
  }
  // A child's path segment is its name (or type) numbered among the earlier siblings of the
  // same name, so inserting a different node elsewhere leaves every other path - and so
  // every node's random() stream - as it was.
  std::map<std::string, int> seen;
  for (const NodeSpec& child : node.children) {
    const std::string& base = child.name.empty() ? child.type : child.name;
    std::string child_path = path;
    child_path.append("/").append(base).append("#").append(std::to_string(seen[base]++));
    NodeAccess::add_child(*made, make_node(child, child_path, blackboard));
  }
  return made;
}

Tree TreeBuilder::build(const Overrides& entries) {
  context = std::make_shared<TreeContext>();
  context->seed = seed;
  create_components();
  check_classifiers_fit_samplers(spec, *context);
  auto blackboard = std::make_shared<Blackboard>(converters);
  for (const auto& [key, text] : entries) blackboard->set<std::string>(key, text);
  const TreeSpec& main = *spec.tree(spec.main);
  auto root = make_node(main.root, main.name + "/" + main.root.type, blackboard);
  return Tree(std::move(root), std::move(blackboard), context, main.name);
}

}  // namespace antipode::bt::detail
