#pragma once
// Collision-free motions of a robot arm in its joint space, planned with OMPL (RRTConnect by
// default) against an ArmCollisionWorld, then shortened.
//
// Units: radians (metres for prismatic joints). A path is a list of joint vectors from the
// start to the goal; the straight joint-space segment between two consecutive ones was
// checked every `resolution_rad` (Euclidean joint-space distance), so no joint moves more
// than that between two checked states.
//
// Threads: plan_arm_motion() may run concurrently with other calls on other worlds, or on
// one world that nothing modifies meanwhile.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/stop_token.hpp"
#include "antipode/robot/kinematic_chain.hpp"
#include "arm_collision_world.hpp"

namespace antipode::planning {

/// The planning problem: the arm, its world, the start and goal, and limits.
struct ArmPlanningProblem {
  const KinematicChain* arm = nullptr;
  const collision::ArmCollisionWorld* world = nullptr;
  Eigen::VectorXd start;
  Eigen::VectorXd goal;
  std::string planner = "RRTConnect";  ///< RRTConnect, RRT, KPIECE1, PRM or EST
  double time_limit_s = 1.0;
  double resolution_rad = 0.02;  ///< joint-space distance between checked states
  /// OMPL's `range`: the longest motion RRTConnect and RRT add at a time (joint-space
  /// distance; KPIECE1 and EST sample within it of a tree state in each joint); 0: OMPL's
  /// default, a fifth of the joint space's longest diagonal (Baxter's arm: about 2.5). Not
  /// for PRM, which connects samples whatever their distance.
  double range_rad = 0.0;
  /// A search that has checked `late_after_states` states without a path goes on with
  /// motions of at most `late_range_rad` (RRTConnect and RRT; the other planners keep their
  /// range): long motions cross open space in few steps, but in a narrow passage nearly every
  /// one meets an obstacle and is thrown away whole, while shorter ones still add states. Both
  /// trees are kept. The switch counts states, not time, so a plan does not depend on the
  /// machine's speed; searches shorter than the budget are not changed at all. 0: keep
  /// `range_rad` to the end.
  double late_range_rad = 1.0;
  long late_after_states = 20000;  ///< see late_range_rad
  /// Check a motion's states as a rake (segment_states.hpp), or in order (false, the
  /// baseline): the same answers, the paths the same.
  bool rake_segments = true;
  std::uint64_t seed = 0;  ///< the planner's samples
  bool shorten = true;     ///< shortcut the path (deterministically)
  StopToken stop;          ///< ends the search early (status kCancelled)
};

enum class PlanStatus {
  kSolved,
  kStartOutsideLimits,
  kGoalOutsideLimits,
  kStartInCollision,
  kGoalInCollision,
  kTimedOut,   ///< no path within the time limit
  kCancelled,  ///< the stop token asked to stop before a path was found
};

const char* to_string(PlanStatus status);

struct ArmPlan {
  PlanStatus status = PlanStatus::kTimedOut;
  std::vector<Eigen::VectorXd> path;  ///< start ... goal, when solved
  std::string detail;                 ///< the contact that makes the start or goal invalid
  double planning_s = 0.0;            ///< OMPL's search
  /// States checked during the search: each motion's up to its first contact, in the order
  /// they were checked.
  long collision_checks = 0;
  double shortening_s = 0.0;  ///< the shortcutting after it
};

/// Plans from `problem.start` to `problem.goal`. Throws antipode::Error for a problem
/// without arm or world, joint vectors of the wrong size, an unknown planner name, a
/// non-positive time limit or resolution, a range that is negative, not finite or given
/// to PRM, or a late range that is negative or not finite, or a negative late budget.
ArmPlan plan_arm_motion(const ArmPlanningProblem& problem);

/// True when the straight joint-space segment from `a` to `b`, checked every `resolution_rad`
/// (both ends included), is free in `world`. Its states are checked as a rake, or in order
/// when `rake` is false (segment_states.hpp); the answer is the same.
bool segment_is_free(const collision::ArmCollisionWorld& world, const Eigen::VectorXd& a,
                     const Eigen::VectorXd& b, double resolution_rad, bool rake = true);

}  // namespace antipode::planning
