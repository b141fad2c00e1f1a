#include "arm_reach.hpp"

#include "antipode/core/error.hpp"

namespace antipode::selectors {

namespace {

// `link` and every link below it.
std::vector<std::string> subtree(const RobotModel& robot, const std::string& link) {
  std::vector<std::string> names;
  for (const std::string& name : robot.link_names()) {
    for (std::string up = name; !up.empty(); up = robot.parent_link(up)) {
      if (up == link) {
        names.push_back(name);
        break;
      }
    }
  }
  return names;
}

}  // namespace

ArmReach::ArmReach(const ArmReachOptions& options)
    : options_(options),
      robot_(RobotModel::load(options.robot_file)),
      arm_(robot_.chain(robot_.root_link(), options.arm_tip)) {
  if (!robot_.has_link(options.points_unchecked_from)) {
    throw Error(options.robot_file + ": no link '" + options.points_unchecked_from + "'" +
                did_you_mean(options.points_unchecked_from, robot_.link_names()));
  }
  for (const std::string& name : subtree(robot_, options.points_unchecked_from))
    if (!robot_.collision_shapes(name).empty()) gripper_links_.push_back(name);
}

collision::ArmCollisionWorld ArmReach::world_for(const Cloud& cloud) const {
  if (cloud.frame != robot_.root_link()) {
    throw Error("cluster_selector: the cloud is in frame '" + cloud.frame +
                    "', but the robot's base is '" + robot_.root_link() + "'",
                {}, "give the selector clouds in the robot's base frame");
  }
  collision::ArmCollisionWorld world(robot_, arm_);
  world.set_points(cloud.points_m, options_.points_resolution_m, gripper_links_);
  return world;
}

Rejection ArmReach::check(const collision::ArmCollisionWorld& world, const Hand& grasp,
                          double standoff_m) const {
  collision::ReachOptions options;
  options.pregrasp_m = standoff_m;
  options.grasp_solutions = options_.ik_solutions;
  collision::Reach reach =
      collision::check_reach(arm_, world, grasp.X_FrameHand, arm_.mid_range(), options);
  if (reach.status != collision::ReachStatus::kReachable) {
    // A parallel gripper turned half a turn about its approach takes the same grasp, with
    // the wrist in another place.
    Eigen::Isometry3d turned = grasp.X_FrameHand;
    turned.linear().col(1) *= -1.0;
    turned.linear().col(2) *= -1.0;
    const collision::Reach other =
        collision::check_reach(arm_, world, turned, arm_.mid_range(), options);
    if (other.status == collision::ReachStatus::kReachable) reach = other;
  }
  switch (reach.status) {
    case collision::ReachStatus::kReachable:
      return Rejection::kNone;
    case collision::ReachStatus::kNoIkAtGrasp:
    case collision::ReachStatus::kNoIkAtPreGrasp:
      return Rejection::kNoIk;
    default:
      return Rejection::kInCollision;
  }
}

}  // namespace antipode::selectors
