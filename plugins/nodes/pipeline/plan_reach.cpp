#include <algorithm>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

Rejection rejection_of(PlanningStatus status) {
  switch (status) {
    case PlanningStatus::kNoIkAtGrasp:
      return Rejection::kNoIk;
    case PlanningStatus::kNoIkAtPreGrasp:
      return Rejection::kNoIkAtPreGrasp;
    case PlanningStatus::kGoalInCollision:
      return Rejection::kInCollision;
    default:
      return Rejection::kNoPlan;
  }
}

/// Plans the arm's motion from the cell's arm state to the selection's grasps, best first,
/// until one is planned; fails when none is.
class PlanReach final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"PlanReach",
            bt::NodeCategory::kAction,
            {bt::component_port<MotionPlanner>("planner", "the motion planner to use"),
             bt::component_port<Cell>("cell", "the cell whose arm moves (its state is the start)"),
             bt::input_port<HandSetPtr>("grasps", "a selection (SelectGrasps), best first"),
             bt::input_port<CloudPtr>("scene", CloudPtr(),
                                      "the observed points the arm must avoid, in the robot's "
                                      "base frame (the whole capture); default: the "
                                      "selection's cloud"),
             bt::input_port<int>("max_grasps", 3, "how many of the selection's grasps to try"),
             bt::input_port<double>("time_limit_s", 0.0,
                                    "the search's limit per grasp; 0: the planner's own"),
             bt::input_port<double>("standoff_m", 0.10, "the pre-grasp, back along the approach"),
             bt::output_port<Trajectory>("trajectory", "the planned motion"),
             bt::output_port<HandSetPtr>(
                 "planned",
                 "the selection with the planned grasp first and the grasps tried before it "
                 "rejected (no IK, in collision, no plan)"),
             bt::output_port<std::string>(
                 "outcome",
                 "on failure: \"no IK\" (no grasp tried has collision-free IK at the grasp and "
                 "pre-grasp), \"no motion plan\" (no path or straight approach), or \"no "
                 "grasp found\" (an empty selection)")},
            0,
            0,
            "Plans the arm's motion to the best grasp it can reach.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr selection = get_input<HandSetPtr>("grasps");
    const MotionPlanner& planner = component<MotionPlanner>("planner");
    PlanningProblem problem;
    problem.start = component<Cell>("cell").arm_state();
    const CloudPtr scene = get_input<CloudPtr>("scene");
    problem.scene = scene ? scene : selection->cloud;
    problem.standoff_m = get_input<double>("standoff_m");
    problem.time_limit_s = get_input<double>("time_limit_s");
    problem.seed = random().seed();
    problem.stop = stop_token();
    const int max_grasps = get_input<int>("max_grasps");

    auto planned = std::make_shared<HandSet>(*selection);
    std::string why = "the selection holds no grasp";
    int tried = 0;
    bool only_ik = true;  // every grasp tried failed for want of a collision-free IK solution
    for (std::size_t i = 0; i < planned->hands.size() && tried < max_grasps; ++i) {
      Hand& grasp = planned->hands[i];
      if (grasp.rejection != Rejection::kNone) continue;
      ++tried;
      problem.grasp = grasp;
      // A planner's fault (it threw, or its solved plan is broken) fails this node: a broken
      // trajectory must never reach the arm.
      PlanningResult result;
      if (const auto error = plugin_error([&] { result = planner.plan(problem); })) {
        set_failure_reason("the planner failed: " + *error);
        return bt::Status::kFailure;
      }
      if (result.solved()) {
        if (const std::string problem_text = plan_problem(result.X_BaseHand, result.trajectory);
            !problem_text.empty()) {
          set_failure_reason("the planner " + problem_text);
          return bt::Status::kFailure;
        }
      }
      if (result.status == PlanningStatus::kCancelled) {
        set_failure_reason("planning cancelled");
        return bt::Status::kFailure;
      }
      if (!result.solved()) {
        grasp.rejection = rejection_of(result.status);
        only_ik = only_ik && grasp.rejection != Rejection::kNoPlan;
        why = std::string(to_string(result.status)) +
              (result.detail.empty() ? "" : " (" + result.detail + ")");
        continue;
      }
      grasp.X_FrameHand = result.X_BaseHand;
      std::rotate(planned->hands.begin(), planned->hands.begin() + std::ptrdiff_t(i),
                  planned->hands.begin() + std::ptrdiff_t(i) + 1);
      set_output("trajectory", std::move(result.trajectory));
      set_output("planned", HandSetPtr(planned));
      return bt::Status::kSuccess;
    }
    set_output("outcome", std::string(tried == 0 ? "no grasp found"
                                      : only_ik  ? "no IK"
                                                 : "no motion plan"));
    set_failure_reason("no grasp planned: " + why);
    return bt::Status::kFailure;
  }
};

}  // namespace

void register_plan_reach(bt::NodeRegistry& registry) { registry.register_node<PlanReach>(); }

}  // namespace antipode::pipeline
