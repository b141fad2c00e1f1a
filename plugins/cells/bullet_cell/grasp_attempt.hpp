#pragma once
// One simulated grasp attempt with a free-floating gripper, judged from ground truth.

#include "antipode/interfaces/cell.hpp"
#include "gripper.hpp"
#include "physics_world.hpp"

namespace antipode::cells {

struct AttemptOptions {
  GripperOptions gripper;
  double standoff_m = 0.10;        ///< start this far back along the approach
  double approach_step_m = 0.002;  ///< per physics step while approaching
  double close_s = 0.5;
  double lift_m = 0.20;
  double lift_speed_m_s = 0.2;
  double hold_s = 1.0;
  double table_top_z_m = -0.295;
};

struct AttemptResult {
  GraspOutcome outcome = GraspOutcome::kNotExecuted;
  int held_object = -1;  ///< the object lifted on success (still in the world)
};

/// Starts `standoff_m` back from `X_BaseHand` (contact there = collision on approach),
/// approaches in small steps until contact or the grasp pose, closes, lifts and holds.
/// Success: an object touches both fingers after the hold, lifted at least half the lift.
/// The gripper is removed afterwards; the world keeps stepping as it does.
AttemptResult attempt_grasp(PhysicsWorld& world, const Eigen::Isometry3d& X_BaseHand,
                            const AttemptOptions& options);

}  // namespace antipode::cells
