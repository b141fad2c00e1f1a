#pragma once
/// @file
/// Tree: a loaded behaviour tree, ready to tick. Made by load_tree_file() (loader.hpp).

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/blackboard.hpp"
#include "antipode/bt/node.hpp"
#include "antipode/bt/observer.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode::bt {

namespace detail {
struct TreeBuilder;
}

/// Owns the nodes, blackboards and components of one loaded tree file, rooted at its `main`
/// tree. Movable, not copyable. Destroying a tree halts whatever is still RUNNING (without
/// telling observers, which may already be gone).
class Tree {
 public:
  Tree(Tree&&) noexcept;
  Tree& operator=(Tree&&) noexcept;
  ~Tree();

  /// Ticks the root once. When the root completes it is reset, so the next tick starts a new
  /// run. If a node throws, everything RUNNING is halted and the Error is rethrown.
  Status tick_once();

  /// Ticks until the root completes, sleeping `sleep` between ticks; returns SUCCESS or
  /// FAILURE.
  Status tick_while_running(std::chrono::milliseconds sleep = std::chrono::milliseconds(1));

  /// Halts every RUNNING node.
  void halt();

  /// Asks every call the tree's nodes make to stop (cooperatively, see stop_token.hpp);
  /// safe from another thread. The calls fail with "cancelled"; it cannot be undone.
  void request_stop();

  Node& root() { return *root_; }
  const Node& root() const { return *root_; }

  /// The main tree's blackboard (`--set key=value` entries live here).
  Blackboard& blackboard() { return *blackboard_; }
  const Blackboard& blackboard() const { return *blackboard_; }

  /// Reports every status change to `observer`, which is not owned and must outlive the
  /// ticking (or be removed).
  void add_observer(TreeObserver* observer);
  /// Same, with the tree keeping `observer` alive.
  void add_observer(std::shared_ptr<TreeObserver> observer);
  void remove_observer(TreeObserver* observer);

  /// Where Log messages go (default: stdout, one line per message).
  void set_log_sink(LogSink sink);
  /// Where Node::progress() reports go (default: nowhere).
  void set_progress_sink(ProgressSink sink);

  /// Calls `visitor` for every node, depth first, parents before children (depth 0 = root).
  void visit(const std::function<void(const Node& node, int depth)>& visitor) const;

  /// The component declared as `name`, or null.
  std::shared_ptr<Component> component(const std::string& name) const;
  /// Names of all components, sorted.
  std::vector<std::string> component_names() const;

  /// The name of the tree the root belongs to (the file's `main`).
  const std::string& main_tree() const { return main_tree_; }
  std::uint64_t seed() const;

 private:
  friend struct detail::TreeBuilder;
  Tree(std::unique_ptr<Node> root, std::shared_ptr<Blackboard> blackboard,
       std::shared_ptr<detail::TreeContext> context, std::string main_tree);

  std::shared_ptr<detail::TreeContext> context_;
  std::shared_ptr<Blackboard> blackboard_;
  std::unique_ptr<Node> root_;
  std::string main_tree_;
};

}  // namespace antipode::bt
