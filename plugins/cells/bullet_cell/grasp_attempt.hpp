#pragma once
// One simulated grasp attempt with a free-floating gripper, judged and recorded from ground
// truth.

#include "antipode/interfaces/grasp_attempt.hpp"
#include "gripper.hpp"
#include "physics_world.hpp"

namespace antipode::cells {

struct AttemptOptions {
  GripperOptions gripper;
  double standoff_m = 0.10;         ///< start this far back along the approach
  double approach_step_m = 0.002;   ///< per physics step while approaching
  double arrive_s = 0.1;            ///< time allowed after the last approach step to settle
  double arrived_m = 0.0005;        ///< settled: the palm face this close to its planned position
  double pose_tolerance_m = 0.003;  ///< palm face this close to its planned position = reached
  double max_close_s = 2.0;     ///< the fingers close until they hold and stall, at most this long
  double stall_window_s = 0.1;  ///< stalled: the aperture changed less than `stall_m` ...
  double stall_m = 0.0002;      ///< ... over the last `stall_window_s`
  double lift_m = 0.20;
  double lift_speed_m_s = 0.2;
  double hold_s = 1.0;
};

struct AttemptResult {
  GraspAttempt record;
  int held_object = -1;  ///< the object lifted on success (still in the world)
};

/// Starts `standoff_m` back from `X_BaseHand` (contact there = collision on approach) and
/// drives the hand to the grasp pose in small steps: the drive is force-bounded, so it
/// pushes light objects and stalls against the table or heavy ones, as a position-controlled
/// arm does. Then it closes until the fingers hold an object and stall, or close fully (a
/// gripper squeezes until its fingers stop on something: judged after a fixed time, fingers
/// still pushing an object across the table counted as empty), lifts and holds. Success: after the
/// hold an object touches both fingers and no fixture (the table, the box). The gripper is removed
/// afterwards; the world keeps stepping as it does.
AttemptResult attempt_grasp(PhysicsWorld& world, const Eigen::Isometry3d& X_BaseHand,
                            const AttemptOptions& options);

}  // namespace antipode::cells
