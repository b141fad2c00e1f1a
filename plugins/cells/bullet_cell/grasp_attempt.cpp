#include "grasp_attempt.hpp"

#include <cmath>
#include <map>

namespace antipode::cells {
namespace {

Eigen::Isometry3d shifted(const Eigen::Isometry3d& pose, const Eigen::Vector3d& by) {
  Eigen::Isometry3d out = pose;
  out.translation() += by;
  return out;
}

// Approaches from the stand-off pose; returns false when the gripper starts in contact.
bool approach(PhysicsWorld& world, Gripper& gripper, const Eigen::Isometry3d& X_BaseHand,
              const AttemptOptions& options) {
  const Eigen::Vector3d direction = X_BaseHand.linear().col(0);
  if (!gripper.touching().empty()) return false;
  const int steps = int(std::ceil(options.standoff_m / options.approach_step_m));
  for (int i = 1; i <= steps; ++i) {
    const double back = options.standoff_m * (1.0 - double(i) / steps);
    gripper.move_to(shifted(X_BaseHand, -back * direction));
    world.step();
    if (!gripper.touching().empty()) break;
  }
  return true;
}

void lift_and_hold(PhysicsWorld& world, Gripper& gripper, const AttemptOptions& options) {
  const double dt = world.options().time_step_s;
  const int steps = std::max(1, int(std::ceil(options.lift_m / (options.lift_speed_m_s * dt))));
  const Eigen::Isometry3d start = gripper.pose();
  for (int i = 1; i <= steps; ++i) {
    const double s = double(i) / steps, eased = s * s * (3.0 - 2.0 * s);  // no jerk at the ends
    gripper.move_to(shifted(start, Eigen::Vector3d(0, 0, options.lift_m * eased)));
    world.step();
  }
  world.step(int(std::ceil(options.hold_s / dt)));
}

}  // namespace

AttemptResult attempt_grasp(PhysicsWorld& world, const Eigen::Isometry3d& X_BaseHand,
                            const AttemptOptions& options) {
  AttemptResult result;
  const double tolerance = 0.002;
  std::map<int, double> start_z;
  for (int id : world.ids(BodyRole::kObject)) start_z[id] = world.pose(id).translation().z();
  {
    const Eigen::Vector3d back = -options.standoff_m * X_BaseHand.linear().col(0);
    Gripper gripper(world, options.gripper, shifted(X_BaseHand, back));
    if (!approach(world, gripper, X_BaseHand, options)) {
      result.outcome = GraspOutcome::kCollisionOnApproach;
      return result;
    }
    gripper.drive_fingers(-options.gripper.finger_speed_m_s);
    world.step(int(std::ceil(options.close_s / world.options().time_step_s)));
    const bool had_object = !gripper.pinched(tolerance).empty();
    if (!had_object) {
      result.outcome = GraspOutcome::kEmptyGrasp;
    } else {
      lift_and_hold(world, gripper, options);
      for (int id : gripper.pinched(tolerance))
        if (world.pose(id).translation().z() > start_z[id] + options.lift_m / 2)
          result.held_object = id;
      result.outcome = result.held_object >= 0 ? GraspOutcome::kSuccess : GraspOutcome::kSlipped;
    }
  }
  return result;
}

}  // namespace antipode::cells
