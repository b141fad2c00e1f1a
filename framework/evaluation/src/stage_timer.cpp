#include "antipode/evaluation/stage_timer.hpp"

#include "antipode/bt/node.hpp"

namespace antipode::evaluation {

void StageTimer::on_status_change(const bt::Node& node, bt::Status, bt::Status current,
                                  std::chrono::steady_clock::time_point when) {
  if (node.category() != bt::NodeCategory::kAction) return;
  if (current != bt::Status::kSuccess && current != bt::Status::kFailure) return;
  seconds_[node.type()] += std::chrono::duration<double>(when - mark_).count();
  mark_ = when;
  if (current == bt::Status::kFailure && first_failure_.empty())
    first_failure_ = node.type() + ": " + node.failure_reason();
}

}  // namespace antipode::evaluation
