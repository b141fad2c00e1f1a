#pragma once
// The built-in leaf nodes: AlwaysSuccess, AlwaysFailure, SetBlackboard, Log and Wait.
// Their semantics are documented in docs/trees.md.

#include <chrono>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"

namespace antipode::bt::builtin {

class AlwaysSuccess : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override { return Status::kSuccess; }
};

class AlwaysFailure : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override { return Status::kFailure; }
};

// Writes `value` (a literal, stored as text, or a copy of another entry) to entry `key`;
// with `if_unset`, only when the entry does not exist yet.
class SetBlackboard : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// Sends `message`, with {key} placeholders expanded, to the tree's log sink.
class Log : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest();

 protected:
  Status tick() override;
};

// RUNNING until `msec` milliseconds have passed since it started, then SUCCESS.
class Wait : public StatefulActionNode {
 public:
  using StatefulActionNode::StatefulActionNode;
  static NodeManifest manifest();

 protected:
  Status on_start() override;
  Status on_running() override;

 private:
  std::chrono::steady_clock::time_point deadline_;
};

}  // namespace antipode::bt::builtin
