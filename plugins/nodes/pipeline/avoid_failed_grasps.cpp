#include <cmath>
#include <limits>
#include <map>
#include <string>
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

// Every executed grasp of `run` that failed, whenever it was.
std::vector<Hand> failed_in_run(const ClearingRun& run) {
  std::vector<Hand> failed;
  for (const ClearingCycle& cycle : run.cycles)
    if (cycle.attempt && cycle.grasp && !cycle.succeeded()) failed.push_back(*cycle.grasp);
  return failed;
}

// The id of the object of `hands` with a point nearest to `centre`, if that point lies within
// `radius_m`; else -1. A failed grasp whose object has since moved away matches nothing.
std::int32_t object_at(const HandSet& hands, const Eigen::Vector3d& centre, double radius_m) {
  std::int32_t nearest = -1;
  double best = radius_m * radius_m;
  for (const SceneObject& object : hands.objects) {
    for (const std::int32_t i : object.points) {
      const double d2 =
          (hands.cloud->points_m[std::size_t(i)].cast<double>() - centre).squaredNorm();
      if (d2 < best) {
        best = d2;
        nearest = object.id;
      }
    }
  }
  return nearest;
}

/// Drops the hands that would grasp where an executed grasp of this clear-the-box run has
/// just failed: on a scene that has not changed, the same grasp fails again (an object jammed
/// against its neighbours, one wider than the open gripper). A hand is dropped when the middle
/// of its closing region lies within `radius_m` of a failed grasp's; the failures counted
/// are those since the last cycle that removed an object. With `failures_per_object` N > 0
/// and a segmented scene (the sampler's `objects: auto`), an object on which N grasps of the
/// run failed is given up whole: each failed grasp counts for the object that now has the point
/// nearest its grasp centre within half the gripper's opening - between where the fingers were
/// (an object that has moved away is a new chance) - and every hand on that object is dropped.
/// Fails when every hand is dropped.
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
             bt::input_port<int>("failures_per_object", 0,
                                 "give up an object after this many failed grasps on it "
                                 "(0: never)"),
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
    const int per_object = get_input<int>("failures_per_object");
    if (per_object < 0)
      fail("failures_per_object",
           "port 'failures_per_object' of " + describe() + " must be 0 (never) or more");
    const ClearingRun& run = get_input_ref<ClearingRun>("run");
    const std::vector<Hand> failed = failed_since_last_removal(run);
    const std::vector<std::int32_t> given_up = objects_given_up(*in, run, per_object);
    if (failed.empty() && given_up.empty()) {
      set_output("kept", in);
      return bt::Status::kSuccess;
    }
    std::vector<Eigen::Vector3d> avoid;
    avoid.reserve(failed.size());
    for (const Hand& grasp : failed) avoid.push_back(centre_in_frame(grasp, *in));
    auto kept = std::make_shared<HandSet>(*in);
    kept->hands.clear();
    for (const Hand& hand : in->hands) {
      const Eigen::Vector3d centre = grasp_centre(hand, in->geometry);
      bool near = false;
      for (const Eigen::Vector3d& point : avoid) near = near || (centre - point).norm() < radius_m;
      for (const std::int32_t object : given_up) near = near || hand.object == object;
      if (!near) kept->hands.push_back(hand);
    }
    const std::size_t dropped = in->hands.size() - kept->hands.size();
    log("dropped " + std::to_string(dropped) + " of " + std::to_string(in->hands.size()) +
        " hands near " + std::to_string(failed.size()) + " failed grasp(s)" +
        (given_up.empty()
             ? std::string()
             : " and on " + std::to_string(given_up.size()) + " object(s) given up after " +
                   std::to_string(per_object) + " failed grasps"));
    const bool any = !kept->hands.empty();
    set_output("kept", HandSetPtr(std::move(kept)));
    if (!any) {
      set_failure_reason("every hand was near a grasp that failed");
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }

 private:
  Eigen::Vector3d centre_in_frame(const Hand& grasp, const HandSet& hands) const {
    if (!hands.hands.empty() && grasp.frame != hands.hands.front().frame)
      fail("run", "a failed grasp is in frame '" + grasp.frame + "' but the hands are in '" +
                      hands.hands.front().frame + "'");
    return grasp_centre(grasp, hands.geometry);
  }

  // The objects of `hands` on which at least `per_object` grasps of the run failed.
  std::vector<std::int32_t> objects_given_up(const HandSet& hands, const ClearingRun& run,
                                             int per_object) const {
    const double radius_m = 0.5 * hands.geometry.max_aperture_m;
    if (per_object == 0 || hands.objects.empty() || !hands.cloud) return {};
    std::map<std::int32_t, int> failures;
    for (const Hand& grasp : failed_in_run(run)) {
      const std::int32_t object = object_at(hands, centre_in_frame(grasp, hands), radius_m);
      if (object >= 0) ++failures[object];
    }
    std::vector<std::int32_t> given_up;
    for (const auto& [object, count] : failures)
      if (count >= per_object) given_up.push_back(object);
    return given_up;
  }
};

}  // namespace

void register_avoid_failed_grasps(bt::NodeRegistry& registry) {
  registry.register_node<AvoidFailedGrasps>();
}

}  // namespace antipode::pipeline
