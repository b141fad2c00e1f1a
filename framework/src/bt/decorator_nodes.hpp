#pragma once
// The built-in decorators: Inverter, ForceSuccess, ForceFailure, Retry, Repeat,
// KeepRunningUntilFailure (also registered as RetryUntilFailure), Timeout, and SubTree.
// Their semantics are documented in docs/trees.md.

#include <chrono>

#include "antipode/bt/decorator_node.hpp"
#include "antipode/bt/node_registry.hpp"

namespace antipode::bt::builtin {

class Inverter : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

class ForceSuccess : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

class ForceFailure : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

class Retry : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  int failed_attempts_ = 0;
};

class Repeat : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
  void halt() override;

 private:
  void report_progress(int cycles) const;
  int cycles_ = 0;
};

class KeepRunningUntilFailure : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest(const std::string& type = "KeepRunningUntilFailure");

 protected:
  Status tick() override;
};

class Timeout : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;

 private:
  Status expire();
  Status tick_child_with_deadline();

  std::chrono::steady_clock::time_point deadline_;
  std::chrono::milliseconds limit_{0};
};

// The root of another tree, ticked with its own blackboard (remapped by the loader).
class SubTree : public DecoratorNode {
 public:
  using DecoratorNode::DecoratorNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

}  // namespace antipode::bt::builtin
