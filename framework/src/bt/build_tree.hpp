#pragma once
// Instantiating a validated FileSpec: components, blackboards and nodes.

#include <memory>
#include <string>

#include "antipode/bt/tree.hpp"
#include "antipode/plugin/component_source.hpp"
#include "overrides.hpp"
#include "tree_spec.hpp"

namespace antipode::bt::detail {

struct TreeBuilder {
  const FileSpec& spec;
  const ComponentSource* components;
  std::shared_ptr<const LiteralConverters> converters;
  std::uint64_t seed = 0;
  std::shared_ptr<TreeContext> context;

  // Creates the components and the main tree; `entries` become string entries of its
  // blackboard.
  Tree build(const Overrides& entries);

 private:
  void create_components();
  std::shared_ptr<Blackboard> subtree_blackboard(const NodeSpec& node,
                                                 const std::shared_ptr<Blackboard>& parent) const;
  std::unique_ptr<Node> make_node(const NodeSpec& node, const std::string& path,
                                  const std::shared_ptr<Blackboard>& blackboard);
};

}  // namespace antipode::bt::detail
