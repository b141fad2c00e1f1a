#include <algorithm>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Executes the best grasp of a selection in a cell, with the selection's gripper; succeeds
/// only when the cell reports success.
class ExecuteGrasp final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ExecuteGrasp",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell that executes"),
             bt::input_port<HandSetPtr>(
                 "grasps",
                 "a selection (SelectGrasps): its first hand without a rejection is "
                 "executed with the set's gripper geometry"),
             bt::input_port<Trajectory>("trajectory", Trajectory{},
                                        "the arm motion to follow; empty = free-floating hand"),
             bt::output_port<std::string>("outcome", "how the attempt ended"),
             bt::output_port<GraspAttempt>("attempt", "the cell's record of the attempt"),
             bt::output_port<Hand>("grasp", "the grasp executed")},
            0,
            0,
            "Executes a grasp and reports the outcome and the attempt's record.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr selection = get_input<HandSetPtr>("grasps");
    const auto best =
        std::find_if(selection->hands.begin(), selection->hands.end(),
                     [](const Hand& hand) { return hand.rejection == Rejection::kNone; });
    if (best == selection->hands.end()) {
      set_failure_reason("the selection holds no grasp to execute");
      return bt::Status::kFailure;
    }
    const GraspRequest request{*best, selection->geometry, get_input<Trajectory>("trajectory")};
    GraspAttempt attempt = component<Cell>("cell").execute(request);
    set_output("outcome", std::string(to_string(attempt.outcome)));
    set_output("grasp", *best);
    log(std::string(to_string(attempt.outcome)) + ": " + attempt.reason);
    const bool success = attempt.outcome == GraspOutcome::kSuccess;
    const std::string reason = attempt.reason;
    set_output("attempt", std::move(attempt));
    if (!success) {
      set_failure_reason("grasp failed: " + reason);
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_execute_grasp(bt::NodeRegistry& registry) { registry.register_node<ExecuteGrasp>(); }

}  // namespace antipode::pipeline
