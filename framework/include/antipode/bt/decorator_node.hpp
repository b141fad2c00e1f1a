#pragma once
/// @file
/// Base class of decorator nodes (nodes with exactly one child).

#include "antipode/bt/node.hpp"

namespace antipode::bt {

/// A node with exactly one child, child(). Halting it halts the child; a subclass with state
/// of its own overrides halt() and calls DecoratorNode::halt().
class DecoratorNode : public Node {
 public:
  using Node::Node;

 protected:
  void halt() override { halt_child(0); }
};

}  // namespace antipode::bt
