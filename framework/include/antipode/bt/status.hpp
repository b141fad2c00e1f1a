#pragma once
/// @file
/// The small enums every behaviour-tree node and observer speaks: a node's status, its
/// category and the direction of its ports.

namespace antipode::bt {

/// What a node reports when ticked. kIdle is never returned by a tick: it is the state of a
/// node that has not started, has completed and been reset, or has been halted.
enum class Status { kIdle, kRunning, kSuccess, kFailure };

/// "IDLE", "RUNNING", "SUCCESS" or "FAILURE".
const char* to_string(Status status);

/// True for kSuccess and kFailure.
inline bool is_completed(Status status) {
  return status == Status::kSuccess || status == Status::kFailure;
}

/// The role of a node type in a tree; it fixes how the YAML grammar reads its children.
enum class NodeCategory { kAction, kCondition, kControl, kDecorator, kSubTree };

/// "action", "condition", "control", "decorator" or "subtree".
const char* to_string(NodeCategory category);

/// kInput ports are read, kOutput ports are written, kInOut ports are both; output and
/// in-out ports always name a blackboard entry.
enum class PortDirection { kInput, kOutput, kInOut };

/// "input", "output" or "inout".
const char* to_string(PortDirection direction);

}  // namespace antipode::bt
