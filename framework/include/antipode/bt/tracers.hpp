#pragma once
/// @file
/// Tracers: observers that record a tree's status changes for people (ConsoleTracer), for
/// tools (JsonlTracer) and to say why a run failed (FailureWitness). Attach them with
/// Tree::add_observer().

#include <chrono>
#include <fstream>
#include <ostream>
#include <string>

#include "antipode/bt/observer.hpp"

namespace antipode::bt {

/// One line per status change, time relative to the tracer's creation:
/// `[  0.012s] SampleHands RUNNING -> SUCCESS`, `[  0.020s] Retry(pick) RUNNING -> FAILURE:
/// failed 3 attempts`, `[  0.031s] Wait RUNNING -> IDLE (halted)`. A node with a `name:` of its
/// own prints as `Type(name)`. With `colour` the statuses are ANSI-coloured.
class ConsoleTracer : public TreeObserver {
 public:
  explicit ConsoleTracer(std::ostream& out, bool colour = false);
  void on_status_change(const Node& node, Status previous, Status current,
                        std::chrono::steady_clock::time_point when) override;

 private:
  std::string status_text(Status status) const;

  std::ostream& out_;
  bool colour_;
  std::chrono::steady_clock::time_point start_;
};

/// One JSON object per line and per status change, flushed at once:
/// `{"time_s":0.012,"node":"SampleHands","type":"SampleHands","path":"detect/Sequence/
/// SampleHands#0","where":"trees/detect.yaml:7:11","from":"RUNNING","to":"FAILURE",
/// "reason":"no hands"}`. `reason` is present only for failures that gave one; `time_s` is
/// seconds since the tracer was created.
class JsonlTracer : public TreeObserver {
 public:
  /// Opens (truncates) `path`; throws antipode::Error when it cannot be written.
  explicit JsonlTracer(const std::string& path);
  void on_status_change(const Node& node, Status previous, Status current,
                        std::chrono::steady_clock::time_point when) override;

 private:
  std::string path_;
  std::ofstream out_;
  std::chrono::steady_clock::time_point start_;
};

/// Remembers the last leaf node (action or condition) that failed with a reason. A control
/// node or decorator fails because a child did, so after a run that failed this is the
/// likeliest cause to show the user: `SampleHands at trees/detect.yaml:18:13: no hand
/// hypothesis found`. Leaves that failed without a reason are not remembered.
class FailureWitness : public TreeObserver {
 public:
  void on_status_change(const Node& node, Status previous, Status current,
                        std::chrono::steady_clock::time_point when) override;

  /// "Type at file:line:column: reason" (the node as Node::describe() names it; without
  /// " at ..." when its place in the file is unknown), "" when no leaf failed with a reason.
  const std::string& last_failure() const { return last_failure_; }

 private:
  std::string last_failure_;
};

}  // namespace antipode::bt
