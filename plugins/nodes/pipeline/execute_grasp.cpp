#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Executes a grasp in a cell; succeeds only when the cell reports success.
class ExecuteGrasp final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ExecuteGrasp",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell that executes"),
             bt::input_port<Hand>("grasp", "the grasp to execute"),
             bt::input_port<Trajectory>("trajectory", Trajectory{},
                                        "the arm motion to follow; empty = free-floating hand"),
             bt::output_port<std::string>("outcome", "how the attempt ended")},
            0,
            0,
            "Executes a grasp and reports the outcome.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const GraspOutcome outcome = component<Cell>("cell").execute(
        get_input<Hand>("grasp"), get_input<Trajectory>("trajectory"));
    set_output("outcome", std::string(to_string(outcome)));
    if (outcome != GraspOutcome::kSuccess) {
      set_failure_reason(std::string("grasp failed: ") + to_string(outcome));
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_execute_grasp(bt::NodeRegistry& registry) { registry.register_node<ExecuteGrasp>(); }

}  // namespace antipode::pipeline
