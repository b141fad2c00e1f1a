#pragma once
/// @file
/// Base classes of leaf nodes: SyncActionNode, StatefulActionNode and ConditionNode.

#include "antipode/bt/node.hpp"

namespace antipode::bt {

/// An action that completes within one tick: tick() returns kSuccess or kFailure only.
class SyncActionNode : public Node {
 public:
  using Node::Node;

 protected:
  bool may_return_running() const final { return false; }
};

/// A condition: a check without side effects that returns kSuccess or kFailure.
class ConditionNode : public Node {
 public:
  using Node::Node;

 protected:
  bool may_return_running() const final { return false; }
};

/// An action that takes several ticks. on_start() is called when the node is ticked while
/// not RUNNING, on_running() on later ticks while it is RUNNING, on_halted() when it is
/// halted while RUNNING.
class StatefulActionNode : public Node {
 public:
  using Node::Node;

 protected:
  virtual Status on_start() = 0;
  virtual Status on_running() = 0;
  virtual void on_halted() {}

 private:
  Status tick() final { return starting() ? on_start() : on_running(); }
  void halt() final { on_halted(); }
};

}  // namespace antipode::bt
