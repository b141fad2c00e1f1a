#pragma once
/// @file
/// Base class of control nodes (nodes with a list of children).

#include "antipode/bt/node.hpp"

namespace antipode::bt {

/// A node with zero or more children (the manifest's min_children/max_children). Halting it
/// halts every child; a subclass with state of its own overrides halt() and calls
/// ControlNode::halt().
class ControlNode : public Node {
 public:
  using Node::Node;

 protected:
  void halt() override { halt_children(); }
};

}  // namespace antipode::bt
