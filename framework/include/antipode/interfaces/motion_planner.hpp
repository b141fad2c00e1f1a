#pragma once
/// @file
/// MotionPlanner: a collision-free arm motion to a grasp (paper section 5.1's reaching).
///
/// Frames and units: the grasp and the scene's points are in the robot's base frame (the
/// cell's base frame); the grasp is X_BaseHand, the hand frame of hand_geometry.hpp (x the
/// approach, y the closing direction, origin the centre of the palm face). Metres, radians,
/// seconds. The planner knows its robot (its parameters name the URDF and the arm).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode {

/// A solid the scene is known to hold, in the base frame: a box of `size_m` (full lengths
/// along its x, y, z) or a cylinder (radius size_m.x(), length size_m.y(), along its z),
/// centred at X_BaseObstacle.
struct Obstacle {
  enum class Shape : std::uint8_t { kBox, kCylinder };
  std::string name;  ///< for contact reports
  Shape shape = Shape::kBox;
  Eigen::Isometry3d X_BaseObstacle = Eigen::Isometry3d::Identity();
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
};

/// What to plan: from `start` to the grasp, through the pre-grasp `standoff_m` back along
/// the approach (0: the grasp pose is itself the goal).
struct PlanningProblem {
  Hand grasp;        ///< frame "base"
  JointState start;  ///< the arm's joints now (Cell::arm_state())
  /// Observed points (base frame); null = none known. A planner may keep the cloud for the
  /// next call on the same one: do not modify it once given.
  std::shared_ptr<const Cloud> scene;
  /// Known solids besides the points (a planning benchmark's scene, fixtures); every link
  /// of the arm, the hand's included, stays clear of them.
  std::vector<Obstacle> obstacles;
  double standoff_m = 0.10;  ///< where the straight approach starts
  /// For the search; <= 0: the planner's own limit. A caller that leaves 1.0 overrides a
  /// limit the planner's parameters set.
  double time_limit_s = 1.0;
  std::uint64_t seed = 0;  ///< the same problem and seed give the same motion
  StopToken stop;          ///< cancellation (a Timeout node's deadline)
};

/// How a planning call ended.
enum class PlanningStatus : std::uint8_t {
  kSolved,
  kStartInCollision,  ///< the arm's start state collides (detail: the contact)
  kStartInvalid,      ///< the start state names other joints or lies outside the limits
  kNoIkAtGrasp,       ///< no collision-free joint values put the hand at the grasp
  kNoIkAtPreGrasp,    ///< ... at the pre-grasp
  kNoApproach,        ///< no continuous, collision-free straight approach
  kGoalInCollision,   ///< every goal found collides (detail: the contact)
  kTimedOut,          ///< no path within the time limit
  kCancelled,         ///< the stop token asked to stop
};

const char* to_string(PlanningStatus status);

struct PlanningResult {
  PlanningStatus status = PlanningStatus::kTimedOut;
  std::string detail;  ///< one line for a person, e.g. "self-collision: A with B"
  /// start -> pre-grasp -> grasp when solved (the last segment the straight approach);
  /// empty otherwise.
  Trajectory trajectory;
  /// The grasp pose the trajectory ends at: the problem's, or the same grasp turned half a
  /// turn about its approach (a parallel gripper takes it either way). Execute this one.
  Eigen::Isometry3d X_BaseHand = Eigen::Isometry3d::Identity();
  double goal_s = 0.0;        ///< seconds finding the goal (IK, the straight approach)
  double search_s = 0.0;      ///< seconds of the path search to the pre-grasp
  double simplify_s = 0.0;    ///< seconds spent shortening the path
  long collision_checks = 0;  ///< arm states checked during the path search

  bool solved() const { return status == PlanningStatus::kSolved; }
};

class MotionPlanner : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kMotionPlanner; }

  /// Plans the arm's motion for `problem`. Failures are statuses; throws antipode::Error
  /// only for a malformed problem (a grasp not in frame "base"). Deterministic for a given
  /// problem and seed when the search ends within its time limit; may be called
  /// concurrently.
  virtual PlanningResult plan(const PlanningProblem& problem) const = 0;
};

}  // namespace antipode
