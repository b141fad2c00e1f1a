#include <cmath>
#include <vector>

#include "antipode/bt/action_node.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "antipode/interfaces/clearing_run.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

// The grasps of `run` the cell executed and that failed, since the last cycle that removed an
// object: the scene they failed in is the scene now (a removal changes it - the neighbour
// that jammed an object may be gone - and clears the list).
std::vector<Hand> failed_since_last_removal(const ClearingRun& run) {
  std::vector<Hand> failed;
  for (const ClearingCycle& cycle : run.cycles) {
    if (cycle.objects_after >= 0 && cycle.objects_after < cycle.objects_before) failed.clear();
    if (cycle.attempt && cycle.grasp && !cycle.succeeded()) failed.push_back(*cycle.grasp);
  }
  return failed;
}

/// Drops the hands that would grasp where an executed grasp of this clear-the-box run has
/// just failed: on a scene that has not changed, the same grasp fails again (an object jammed
/// against its neighbours, one wider than the open gripper). A hand is dropped when the middle
/// of its closing region lies within `radius_m` of a failed grasp's; the failures counted
/// are those since the last cycle that removed an object. Fails when every hand is dropped.
class AvoidFailedGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"AvoidFailedGrasps",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("hands", "hands to filter (the cloud's frame)"),
             bt::input_port<ClearingRun>("run", "the run so far (ClearBox's `run`)"),
             bt::input_port<double>("radius_m", 0.02,
                                    "drop hands whose grasp centre is this close to a "
                                    "failed grasp's"),
             bt::output_port<HandSetPtr>("kept", "the hands not dropped")},
            0,
            0,
            "Drops hands where a grasp of this clear-the-box run just failed.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr in = get_input<HandSetPtr>("hands");
    const double radius_m = get_input<double>("radius_m");
    if (!(radius_m >= 0.0 && radius_m <= 1.0))
      fail("radius_m", "port 'radius_m' of " + describe() + " must be in [0, 1] m");
    const std::vector<Hand> failed = failed_since_last_removal(get_input_ref<ClearingRun>("run"));
    if (failed.empty()) {
      set_output("kept", in);
      return bt::Status::kSuccess;
    }
    std::vector<Eigen::Vector3d> avoid;
    for (const Hand& grasp : failed) {
      if (!in->hands.empty() && grasp.frame != in->hands.front().frame)
        fail("run", "a failed grasp is in frame '" + grasp.frame + "' but the hands are in '" +
                        in->hands.front().frame + "'");
      avoid.push_back(grasp_centre(grasp, in->geometry));
    }
    auto kept = std::make_shared<HandSet>(*in);
    kept->hands.clear();
    for (const Hand& hand : in->hands) {
      const Eigen::Vector3d centre = grasp_centre(hand, in->geometry);
      bool near = false;
      for (const Eigen::Vector3d& point : avoid) near = near || (centre - point).norm() < radius_m;
      if (!near) kept->hands.push_back(hand);
    }
    const std::size_t dropped = in->hands.size() - kept->hands.size();
    log("dropped " + std::to_string(dropped) + " of " + std::to_string(in->hands.size()) +
        " hands near " + std::to_string(failed.size()) + " failed grasp(s)");
    const bool any = !kept->hands.empty();
    set_output("kept", HandSetPtr(std::move(kept)));
    if (!any) {
      set_failure_reason("every hand was near a grasp that failed");
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_avoid_failed_grasps(bt::NodeRegistry& registry) {
  registry.register_node<AvoidFailedGrasps>();
}

}  // namespace antipode::pipeline
