#pragma once
/// @file
/// Tracers: observers that record a tree's status changes for people (ConsoleTracer) and for
/// tools (JsonlTracer). Attach them with Tree::add_observer().

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
/// SampleHands#1","where":"trees/detect.yaml:7:11","from":"RUNNING","to":"FAILURE",
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

}  // namespace antipode::bt
