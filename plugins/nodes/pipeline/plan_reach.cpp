#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Plans an arm motion to a grasp; fails with the planner's reason when there is none.
class PlanReach final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"PlanReach",
            bt::NodeCategory::kAction,
            {bt::component_port<MotionPlanner>("planner", "the motion planner to use"),
             bt::input_port<Hand>("grasp", "the grasp to reach"),
             bt::input_port<std::vector<double>>("start_rad", std::vector<double>{},
                                                 "start joint positions"),
             bt::input_port<double>("time_limit_s", 1.0, "planning time limit"),
             bt::output_port<Trajectory>("trajectory", "the planned motion")},
            0,
            0,
            "Plans a collision-free arm motion to a grasp.",
            {}};
  }

 protected:
  bt::Status tick() override {
    PlanningRequest request;
    request.grasp = get_input<Hand>("grasp");
    request.start_rad = get_input<std::vector<double>>("start_rad");
    request.time_limit_s = get_input<double>("time_limit_s");
    std::string why;
    Trajectory trajectory = component<MotionPlanner>("planner").plan(request, &why);
    if (trajectory.empty()) {
      set_failure_reason(why.empty() ? "no motion plan found" : why);
      return bt::Status::kFailure;
    }
    set_output("trajectory", std::move(trajectory));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_plan_reach(bt::NodeRegistry& registry) { registry.register_node<PlanReach>(); }

}  // namespace antipode::pipeline
