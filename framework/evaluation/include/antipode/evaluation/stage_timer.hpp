#pragma once
// Seconds per stage of a tree run: the time each action node took, summed by node type.

#include <chrono>
#include <map>
#include <string>

#include "antipode/bt/observer.hpp"

namespace antipode::evaluation {

/// An observer that charges the time since the previous action node finished (or since
/// start()) to each action node when it finishes, summed by node type: in a sequence of
/// actions that is each action's own time. The first action node that fails is remembered.
class StageTimer final : public bt::TreeObserver {
 public:
  void start() {
    mark_ = std::chrono::steady_clock::now();
    seconds_.clear();
    first_failure_.clear();
  }
  void on_status_change(const bt::Node& node, bt::Status previous, bt::Status current,
                        std::chrono::steady_clock::time_point when) override;

  const std::map<std::string, double>& seconds() const { return seconds_; }
  /// "Type: reason" of the first action node that failed, "" when none did.
  const std::string& first_failure() const { return first_failure_; }

 private:
  std::chrono::steady_clock::time_point mark_;
  std::map<std::string, double> seconds_;
  std::string first_failure_;
};

}  // namespace antipode::evaluation
