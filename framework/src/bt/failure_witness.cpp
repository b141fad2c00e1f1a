#include "antipode/bt/node.hpp"
#include "antipode/bt/tracers.hpp"

namespace antipode::bt {

void FailureWitness::on_status_change(const Node& node, Status /*previous*/, Status current,
                                      std::chrono::steady_clock::time_point /*when*/) {
  if (current != Status::kFailure || node.child_count() != 0 || node.failure_reason().empty())
    return;
  const std::string where = node.where().str();
  last_failure_ =
      node.describe() + (where.empty() ? "" : " at " + where) + ": " + node.failure_reason();
}

}  // namespace antipode::bt
