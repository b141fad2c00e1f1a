#include <algorithm>

#include "checks.hpp"

namespace antipode::bt::detail {
namespace {

struct CycleSearch {
  const FileSpec& spec;
  std::vector<std::string> stack;  // trees being expanded, outermost first
  std::vector<std::string> done;   // trees known to be free of cycles

  void visit_tree(const TreeSpec& tree) {
    if (std::find(done.begin(), done.end(), tree.name) != done.end()) return;
    stack.push_back(tree.name);
    visit_node(tree.root);
    stack.pop_back();
    done.push_back(tree.name);
  }

  void visit_node(const NodeSpec& node) {
    if (!node.subtree.empty()) {
      const auto open = std::find(stack.begin(), stack.end(), node.subtree);
      if (open != stack.end()) {
        std::string cycle;
        for (auto name = open; name != stack.end(); ++name) cycle += *name + " -> ";
        throw Error("subtree cycle: " + cycle + node.subtree, node.subtree_where);
      }
      visit_tree(*spec.tree(node.subtree));
    }
    for (const auto& child : node.children) visit_node(child);
  }
};

}  // namespace

void check_subtree_cycles(const FileSpec& spec) {
  CycleSearch search{spec, {}, {}};
  for (const auto& tree : spec.trees) search.visit_tree(tree);
}

}  // namespace antipode::bt::detail
