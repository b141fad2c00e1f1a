#pragma once
// The built-in control nodes: Sequence, ReactiveSequence, Fallback, ReactiveFallback and
// Parallel. Their semantics are documented in docs/trees.md.

#include <set>

#include "antipode/bt/control_node.hpp"
#include "antipode/bt/node_registry.hpp"

namespace antipode::bt::builtin {

// Sequence and Fallback are the same node with the roles of SUCCESS and FAILURE swapped:
// both tick their children in order while each returns `keep_going`, and stop at the
// first child that returns the other completed status.

// Ticks children in order while they return `keep_going`; remembers a RUNNING child and
// resumes there on the next tick.
class OrderedControl : public ControlNode {
 public:
  OrderedControl(const NodeConfig& config, Status keep_going)
      : ControlNode(config), keep_going_(keep_going) {}

 protected:
  Status tick() override;
  void halt() override;

 private:
  Status keep_going_;
  std::size_t current_ = 0;
};

// Ticks children from the first on every tick while they return `keep_going`; a RUNNING
// child halts the others.
class ReactiveControl : public ControlNode {
 public:
  ReactiveControl(const NodeConfig& config, Status keep_going)
      : ControlNode(config), keep_going_(keep_going) {}

 protected:
  Status tick() override;

 private:
  Status keep_going_;
};

class Sequence : public OrderedControl {
 public:
  explicit Sequence(const NodeConfig& config) : OrderedControl(config, Status::kSuccess) {}
  static NodeManifest manifest();
};

class ReactiveSequence : public ReactiveControl {
 public:
  explicit ReactiveSequence(const NodeConfig& config) : ReactiveControl(config, Status::kSuccess) {}
  static NodeManifest manifest();
};

class Fallback : public OrderedControl {
 public:
  explicit Fallback(const NodeConfig& config) : OrderedControl(config, Status::kFailure) {}
  static NodeManifest manifest();
};

class ReactiveFallback : public ReactiveControl {
 public:
  explicit ReactiveFallback(const NodeConfig& config) : ReactiveControl(config, Status::kFailure) {}
  static NodeManifest manifest();
};

// Ticks all children on every tick until a success or failure threshold is reached.
class Parallel : public ControlNode {
 public:
  using ControlNode::ControlNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  int threshold(const std::string& port) const;
  Status finish(Status result);

  std::set<std::size_t> completed_;
  int successes_ = 0;
  int failures_ = 0;
};

}  // namespace antipode::bt::builtin
