#include <algorithm>
#include <unordered_set>

#include "checks.hpp"

namespace antipode::bt::detail {
namespace {

struct CycleSearch {
  const FileSpec& spec;
  std::vector<std::string> stack;        // trees being expanded, outermost first
  std::unordered_set<std::string> done;  // trees known to be free of cycles

  void visit_tree(const TreeSpec& tree, const SourceLocation& where) {
    if (done.count(tree.name)) return;
    if (stack.size() >= kMaxSubtreeDepth) {
      throw Error("subtrees nest deeper than " + std::to_string(kMaxSubtreeDepth) + " (" +
                      stack.front() + " -> ... -> " + stack.back() + " -> " + tree.name + ")",
                  where);
    }
    stack.push_back(tree.name);
    visit_node(tree.root);
    stack.pop_back();
    done.insert(tree.name);
  }

  void visit_node(const NodeSpec& node) {
    if (!node.subtree.empty()) {
      const auto open = std::find(stack.begin(), stack.end(), node.subtree);
      if (open != stack.end()) {
        std::string cycle;
        for (auto name = open; name != stack.end(); ++name) cycle += *name + " -> ";
        throw Error("subtree cycle: " + cycle + node.subtree, node.subtree_where);
      }
      visit_tree(*spec.tree(node.subtree), node.subtree_where);
    }
    for (const auto& child : node.children) visit_node(child);
  }
};

}  // namespace

void check_subtree_cycles(const FileSpec& spec) {
  CycleSearch search{spec, {}, {}};
  for (const auto& tree : spec.trees) search.visit_tree(tree, SourceLocation{});
}

}  // namespace antipode::bt::detail
