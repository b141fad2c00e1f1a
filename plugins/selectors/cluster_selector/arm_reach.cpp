#include "arm_reach.hpp"

#include "antipode/core/error.hpp"
#include "collision_pairs.hpp"

namespace antipode::selectors {

ArmReach::ArmReach(const ArmReachOptions& options)
    : options_(options),
      robot_(RobotModel::load(options.robot_file)),
      arm_(robot_.chain(robot_.root_link(), options.arm_tip)) {
  gripper_links_ = collision::shaped_links_below(robot_, options.points_unchecked);
}

collision::ArmCollisionWorld ArmReach::world_for(const Cloud& cloud) const {
  if (cloud.frame != robot_.root_link()) {
    throw Error("cluster_selector: the cloud is in frame '" + cloud.frame +
                    "', but the robot's base is '" + robot_.root_link() + "'",
                {}, "give the selector clouds in the robot's base frame");
  }
  collision::ArmCollisionWorld world(robot_, arm_, {}, options_.collision);
  world.set_points(cloud.points_m, options_.points_resolution_m, gripper_links_);
  return world;
}

Rejection ArmReach::check(const collision::ArmCollisionWorld& world, const Hand& grasp,
                          double standoff_m, const JointState& start) const {
  const Eigen::VectorXd seed =
      start.names == arm_.joint_names() ? joint_vector(start.positions_rad) : arm_.mid_range();
  collision::ReachOptions options;
  options.pregrasp_m = standoff_m;
  options.grasp_solutions = options_.ik_solutions;
  options.search = options_.search;
  options.ik.solver = options_.ik_solver;
  collision::Reach reach = collision::check_reach(arm_, world, grasp.X_FrameHand, seed, options);
  if (reach.status != collision::ReachStatus::kReachable) {
    // A parallel gripper turned half a turn about its approach takes the same grasp.
    const collision::Reach other = collision::check_reach(
        arm_, world, collision::half_turned(grasp.X_FrameHand), seed, options);
    if (other.status == collision::ReachStatus::kReachable) reach = other;
  }
  switch (reach.status) {
    case collision::ReachStatus::kReachable:
      return Rejection::kNone;
    case collision::ReachStatus::kNoIkAtGrasp:
      return Rejection::kNoIk;
    case collision::ReachStatus::kNoIkAtPreGrasp:
      return Rejection::kNoIkAtPreGrasp;
    default:
      return Rejection::kInCollision;
  }
}

}  // namespace antipode::selectors
