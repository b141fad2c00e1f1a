#pragma once
// The built-in control nodes: Sequence, ReactiveSequence, Fallback, ReactiveFallback and
// Parallel. Their semantics are documented in docs/trees.md.

#include <set>

#include "antipode/bt/control_node.hpp"
#include "antipode/bt/node_registry.hpp"

namespace antipode::bt::builtin {

// Ticks children in order; remembers a RUNNING child and resumes there on the next tick.
class Sequence : public ControlNode {
 public:
  using ControlNode::ControlNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  std::size_t current_ = 0;
};

// Ticks children from the first on every tick.
class ReactiveSequence : public ControlNode {
 public:
  using ControlNode::ControlNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Tries children in order until one succeeds; remembers a RUNNING child.
class Fallback : public ControlNode {
 public:
  using ControlNode::ControlNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  std::size_t current_ = 0;
};

// Tries children from the first on every tick.
class ReactiveFallback : public ControlNode {
 public:
  using ControlNode::ControlNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
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
