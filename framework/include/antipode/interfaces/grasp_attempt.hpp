#pragma once
/// @file
/// What a cell is asked to execute (GraspRequest) and what it reports back (GraspAttempt).
///
/// Frames and units: poses are X_BaseHand, the hand frame of hand_geometry.hpp (x approach,
/// y closing, origin at the centre of the palm face) in the cell's base frame; metres,
/// seconds. A cell fills every field it can observe; a real cell without ground truth
/// leaves the object fields empty.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/trajectory.hpp"

namespace antipode {

/// How a grasp attempt ended, judged by the cell (ground truth in simulation).
enum class GraspOutcome : std::uint8_t {
  kSuccess,
  kArmCollision,  ///< an arm link touched the environment on the way to the pre-grasp
  kCollisionOnApproach,
  kEmptyGrasp,
  kSlipped,
  kObjectKnockedOut,
  kNotExecuted,  ///< stays last: code iterates kSuccess .. kNotExecuted
};

const char* to_string(GraspOutcome outcome);

/// One grasp to execute.
struct GraspRequest {
  Hand grasp;            ///< pose in frame "base", fingers fully open
  HandGeometry gripper;  ///< the gripper the grasp was planned for (the hand set's geometry)
  /// The arm's motion to the grasp (start -> pre-grasp -> grasp, as MotionPlanner plans it);
  /// empty = a free-floating hand.
  Trajectory trajectory;
};

/// The record of one attempt: enough to tell why it failed without running it again.
struct GraspAttempt {
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

  GraspOutcome outcome = GraspOutcome::kNotExecuted;
  /// One line for a person: what happened, e.g. "the +y finger touched 025_mug 23 mm before
  /// the pose; the fingers closed on nothing".
  std::string reason;

  // The approach.
  Eigen::Isometry3d X_BaseHand_planned = Eigen::Isometry3d::Identity();
  /// The hand's pose when the fingers began to close.
  Eigen::Isometry3d X_BaseHand_closing = Eigen::Isometry3d::Identity();
  /// Distance from the planned to the actual palm-face centre when the fingers began to close.
  double pose_error_m = kUnknown;
  /// The palm face was within the cell's tolerance of its planned position.
  bool reached_pose = false;
  /// What the gripper touched when it stopped short of the pose (or at the stand-off pose),
  /// as "part: body" entries, e.g. "finger +y: 025_mug"; empty when it reached the pose.
  std::vector<std::string> stopped_by;
  /// The first thing the gripper touched on its way in ("finger +y: 025_mug"), "" if none.
  std::string first_contact;
  /// How far the palm face still was from its planned position at that first touch.
  double first_contact_before_pose_m = kUnknown;

  // The closing.
  /// Inner distance between the fingers when they stopped closing.
  double opening_at_contact_m = kUnknown;
  /// Objects in the planned closing region before the attempt (ground truth at detection).
  std::vector<std::string> between_fingers_at_detection;
  /// What the gripper's fingers and palm would overlap at the planned pose before the
  /// attempt ("finger +y: 025_mug"): the planned pose itself collides with the true scene.
  std::vector<std::string> in_collision_at_planned_pose;
  /// Objects in the closing region of the actual hand pose when the fingers began to close.
  std::vector<std::string> between_fingers_at_closing;
  /// What the gripper's parts touched, within 2 mm (the pinch's tolerance: a finger pressing
  /// on an object in clutter was seen resting 1-2 mm off it), when the fingers stopped closing
  /// ("finger +y: ellipsoid", "finger -y: box wall"): why fingers that met something pinched
  /// nothing.
  std::vector<std::string> touching_at_closing;
  /// The object both fingers held after closing ("" when none).
  std::string pinched_object;
  /// Where the scene really was when the fingers stopped closing: points on its true
  /// surfaces (objects, box, table) about 2.5 mm apart, within 8 cm of the middle of the closing
  /// region along each hand axis (X_BaseHand_closing), in the base frame; at most 60,000.
  /// What a picture of the attempt draws over the cloud the grasp was found in (an object
  /// pushed aside, tipped, or rolled out from between the fingers). Empty when the fingers
  /// never closed, and from a cell without ground truth.
  std::vector<Eigen::Vector3f> surface_at_closing_m;

  // The lift.
  /// The highest the pinched object rose during the lift and hold (0 when nothing was
  /// pinched); it may have fallen back since.
  double lift_m = 0.0;
  /// Simulated (or real) seconds the attempt took.
  double duration_s = 0.0;
};

}  // namespace antipode
