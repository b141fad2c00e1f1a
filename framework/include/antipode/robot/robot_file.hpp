#pragma once
/// @file
/// Robot files: one arm of a robot, named once for every part of a tree that uses it (the
/// cell, the selector's reach check, the planner, the drawings). The shipped ones are
/// robots/baxter/baxter.yaml and robots/panda/panda.yaml (docs/robot.md, "Bringing your own
/// robot"):
///
///     name: Franka Emika Panda               # optional: how reports name it
///     urdf: panda.urdf                       # the robot, relative to this file
///     arm_tip: panda_grasp                   # the grasp frame; the arm runs from the root
///     gripper_from: panda_hand               # this link and those below it are the hand
///     points_unchecked: [panda_leftfinger, panda_rightfinger]  # optional (see below)
///     home_rad: [0, -0.785, 0, -2.356, 0, 1.571, 0.785]
///     gripper: ../grippers/franka_hand.yaml  # the hand's geometry (a gripper file)
///     model: ../../models/hog_svm_franka.model  # optional: a classifier for that gripper
///     success_model: my_outcome.model        # optional: its grasp-success model
///
/// Frames and units: the URDF's root link is the robot's base frame, the frame clouds and
/// grasps are given in (the cell's frame: a robot's placement in the cell is the URDF's own
/// fixed joints). `arm_tip` is the hand frame of HandGeometry (docs/pose-convention.md): x
/// the approach, y the closing direction, origin the centre of the palm face. Radians.
///
/// `points_unchecked` names the links that may touch the object being grasped: they and the
/// links below them are not checked against the observed points when the arm's reach and
/// motion are planned (the fingers enclose the target's points). Without it, the whole hand
/// (`gripper_from` and below) is left unchecked: right for a hand no wider than the gripper
/// file's palm, which the sampler checks against the points itself. `model` is the classifier
/// trained on the paper's near-antipodal labels; `success_model` one trained on the cell's
/// grasp outcomes, whose score is a probability of success (docs/training.md), which
/// `hog_svm_classifier` takes with `labels: outcome`. Every key but `name`, `model`,
/// `success_model` and `points_unchecked` is required: a file that left one out would
/// silently describe part of another robot.

#include <string>
#include <vector>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/parameters.hpp"

namespace antipode {

/// A robot read from a robot file; every path resolved, every link checked against the URDF.
struct RobotFile {
  std::string path;          ///< the file read
  std::string name;          ///< its `name`, or the URDF's robot name
  std::string urdf_path;     ///< the URDF
  std::string arm_tip;       ///< the grasp frame, the arm chain's tip (chain: root -> arm_tip)
  std::string gripper_from;  ///< the hand's first link, on the chain to arm_tip
  /// Links (each with those below it) not checked against observed points; [gripper_from]
  /// unless the file names others, each a link of the URDF.
  std::vector<std::string> points_unchecked;
  std::vector<double> home_rad;  ///< one value per moving joint of the chain, within limits
  std::string gripper_path;      ///< the gripper file
  HandGeometry gripper;          ///< its geometry
  std::string model_path;        ///< the HOG + SVM model trained for it; "" when not named
  /// The HOG + SVM model trained on grasp outcomes for it; "" when not named.
  std::string success_model_path;
};

/// Reads the robot file at `path`. Throws antipode::Error with one line naming the file and,
/// where there is one, the key and its line, for: a missing or unreadable file, YAML that is
/// not a map, a missing or unknown key (with the nearest known one), a URDF that does not
/// load, an `arm_tip` or `gripper_from` that is not a link (with the nearest name) or not on
/// the arm, a home configuration of the wrong size or outside the joint limits, and a
/// gripper file that does not read. Given a URDF instead, says to name its robot file.
/// Thread-safe.
RobotFile read_robot_file(const std::string& path);

/// The robot file a component's `key` parameter names, resolved with resolve_path() against
/// the parameters' file; its errors are located at the parameter.
RobotFile robot_file_parameter(const Parameters& params, const std::string& key);

}  // namespace antipode
