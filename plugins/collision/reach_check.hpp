#pragma once
// Can the arm take a grasp? Inverse kinematics at the grasp and at the pre-grasp (the grasp
// moved back along its approach), each solution checked in the arm's collision world - the
// first filters of the paper's grasp selection (section 5.1) for a hand on an arm.
//
// Frames: X_BaseHand is the hand frame of the grasp (docs/pose-convention.md: x the
// approach) in the robot's base frame; the arm chain's tip must be that hand frame (for
// Baxter, `right_gripper`). Metres and radians.
//
// The world is checked as given: the caller leaves out of it what the hand may touch (the
// target's points between the fingers and along the final approach).

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/inverse_kinematics.hpp"
#include "arm_collision_world.hpp"

namespace antipode::collision {

enum class ReachStatus {
  kReachable,
  kNoIkAtGrasp,            ///< no joint values within the limits put the hand there
  kInCollisionAtGrasp,     ///< the hand alone meets the scene at the grasp (whatever IK would
                           ///< find), or every solution found at the grasp is in collision
  kNoIkAtPreGrasp,         ///< no solution near a free grasp one reaches the pre-grasp
  kInCollisionAtPreGrasp,  ///< the hand alone meets the scene at the pre-grasp (whatever IK
                           ///< would find), or the pre-grasp solutions are in collision
};

const char* to_string(ReachStatus status);

/// How check_reach searches. Every mode gives the same status: they differ in which free
/// pre-grasp solution they return and in how much IK they solve to find it.
enum class ReachSearch {
  /// Solutions at the grasp one at a time, each checked as it is found; for a free one, the
  /// pre-grasp's likewise; the first free pair is the answer. Whether, not how: the
  /// selector's check, which solves as little IK as a reachable grasp needs.
  kFirstFree,
  /// Solutions at the grasp one at a time; for a free one, every pre-grasp solution, and
  /// the free one nearest it (the straight approach between them): the planner's goal.
  kNearestPreGrasp,
  /// Every solution at the grasp first, then as kNearestPreGrasp: the same answer as
  /// kNearestPreGrasp after more IK, kept as the baseline the reach bench measures against.
  kExhaustive,
};

const char* to_string(ReachSearch search);
/// "first_free", "nearest_pregrasp" or "exhaustive"; throws antipode::Error for another name.
ReachSearch reach_search(const std::string& name);

struct ReachOptions {
  double pregrasp_m = 0.10;  ///< how far back along the approach the pre-grasp is
  int grasp_solutions = 12;  ///< distinct IK solutions tried at the grasp (and the pre-grasp)
  ReachSearch search = ReachSearch::kNearestPreGrasp;
  IkOptions ik;  ///< tolerance, budget and seed of each IK call
};

struct Reach {
  ReachStatus status = ReachStatus::kNoIkAtGrasp;
  Eigen::VectorXd q_grasp;     ///< when reachable
  Eigen::VectorXd q_pregrasp;  ///< when reachable
  std::string detail;          ///< the contact behind a kInCollision status
};

/// The same grasp for a parallel gripper turned half a turn about its approach (closing and
/// hand axis reversed): the fingers swap places, the wrist stands elsewhere.
Eigen::Isometry3d half_turned(const Eigen::Isometry3d& X_BaseHand);

/// First the hand alone (ArmCollisionWorld::check_tip_links): a hand in contact at the grasp
/// is kInCollisionAtGrasp, at the pre-grasp kInCollisionAtPreGrasp, whatever IK would find
/// (kExhaustive asks this last, after its IK, and its answer stands: the same status). Then tries
/// up to `grasp_solutions` distinct IK solutions at the grasp (from `q_seed`), in the order IK
/// finds them; for each free one, solves the pre-grasp from it (as many solutions) and takes a free
/// one (`options.search`). Returns the first pair that is free, else the status of the
/// attempt that came farthest (pre-grasp statuses before grasp ones). Throws antipode::Error
/// for a seed or target IK refuses, or invalid options.
Reach check_reach(const KinematicChain& arm, const ArmCollisionWorld& world,
                  const Eigen::Isometry3d& X_BaseHand, const Eigen::VectorXd& q_seed,
                  const ReachOptions& options = {});

}  // namespace antipode::collision
