#pragma once
// The arm's part of grasp selection (paper section 5.1): a grasp is kept only when the arm
// has collision-free joint values at it and at the stand-off (the pre-grasp), checked with
// the robot's collision world (antipode_collision) holding the observed points.
//
// The cloud must be in the robot's base frame (the frame named like the URDF's root link).
// The gripper's links - `points_unchecked` and those below them - are not checked against the
// points: the selector's own hand check (hand_clearance.hpp) is finer and lets the fingers
// enclose the target.

#include <memory>
#include <optional>
#include <string>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "reach_check.hpp"

namespace antipode::selectors {

struct ArmReachOptions {
  std::string robot_file;                     ///< URDF; "" = a free-floating hand (no check)
  std::string arm_tip;                        ///< the grasp frame; the chain starts at the root
  std::vector<std::string> points_unchecked;  ///< RobotFile::points_unchecked
  double points_resolution_m = 0.01;          ///< the octree of the observed points
  /// How the arm's states are checked: FCL alone by default. A selection builds the world of
  /// its capture and checks a few hundred states in it, too few for the spheres' distance
  /// grid to pay for its building (docs/selection.md).
  collision::CollisionOptions collision{collision::CheckMode::kExact};
  int ik_solutions = 12;  ///< distinct IK solutions tried at a grasp
  /// How the IK solutions are searched (the same answers; exhaustive is the slow baseline).
  collision::ReachSearch search = collision::ReachSearch::kFirstFree;
  /// The IK solver: the damped solver (kDampedLeastSquares), or the same with orocos-kdl's
  /// kinematics (kDampedLeastSquaresKdl: the slow baseline).
  IkSolver ik_solver = IkSolver::kDampedLeastSquares;
};

class ArmReach {
 public:
  /// Loads the robot. Throws antipode::Error for a bad file or link.
  explicit ArmReach(const ArmReachOptions& options);

  /// The arm's world for one cloud: the robot and the cloud's points. Throws
  /// antipode::Error when the cloud is not in the robot's base frame.
  collision::ArmCollisionWorld world_for(const Cloud& cloud) const;

  /// kNone when the arm reaches `grasp` (as it is or turned half a turn about its approach:
  /// the same grasp for a parallel gripper) and its pre-grasp `standoff_m` back, else kNoIk,
  /// kNoIkAtPreGrasp or kInCollision (the status of the grasp as it is).
  /// The IK search starts from `start` when it names the arm's joints, else from the middle
  /// of the joint ranges.
  Rejection check(const collision::ArmCollisionWorld& world, const Hand& grasp, double standoff_m,
                  const JointState& start = {}) const;

 private:
  ArmReachOptions options_;
  RobotModel robot_;
  KinematicChain arm_;
  std::vector<std::string> gripper_links_;  // points_unchecked and the links below them
};

}  // namespace antipode::selectors
