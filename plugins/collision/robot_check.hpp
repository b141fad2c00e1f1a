#pragma once
// The checks of a robot file that tell a new robot's author whether the files are right
// (docs/robot.md, "Bringing your own robot"): its arm's kinematics and limits, self-collision
// at home and at random configurations (a histogram of the pairs, to find a bad shape), reach
// over the cell's table and box, and whether the URDF's fingers match the gripper file.
//
// Frames and units: the robot's base frame (the URDF's root), metres, radians.
// Threads: check_robot() is reentrant; it runs on the calling thread.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"
#include "antipode/robot/robot_file.hpp"

namespace antipode::collision {

struct RobotCheckOptions {
  int configurations = 1000;   ///< random configurations for the self-collision histogram
  std::uint64_t seed = 1;      ///< their random stream
  std::string scene_path;      ///< a cell scene file with `table` and `box`; "" = no reach grid
  int grid = 5;                ///< reach grid points per side of the box floor (the table: 2x)
  double tolerance_m = 0.002;  ///< how far the fingers may differ from the gripper file
};

/// How often the first contact found was this pair, over the random configurations.
struct PairCount {
  std::string link, other;
  int count = 0;
};

/// Top-down grasps over one region (the box floor, the table around it), every closing
/// direction of `yaws`, each tried as the selector does (the hand half turned too).
struct ReachGrid {
  std::string region;
  int grasps = 0;
  int reachable = 0;
  int points = 0;                       ///< grid points
  int points_reachable = 0;             ///< those where some closing direction is reachable
  int points_hand_blocked = 0;          ///< unreachable only because the hand touches the scene
  std::map<std::string, int> failures;  ///< by reach status
};

/// One quantity of the gripper as the URDF's fingers make it and as the gripper file says.
struct GripperMatch {
  std::string quantity;  ///< "closed aperture", "open aperture", "finger reach", ...
  double urdf_m = 0.0;
  double file_m = 0.0;
  bool required = true;  ///< a mismatch is a problem (else it is reported only)
  bool ok = true;
};

struct RobotCheck {
  std::string name;
  KinematicChain arm;                  ///< the root -> arm_tip chain
  Eigen::Isometry3d X_BaseGrasp_home;  ///< the grasp frame at home
  double reach_m = 0.0;                ///< farthest grasp frame from the first moving joint
  std::string home_contact;            ///< "free", or the contact at home
  int configurations = 0;
  int self_colliding = 0;
  std::vector<PairCount> pairs;  ///< most frequent first
  std::size_t self_pairs = 0;    ///< the pairs checked
  std::vector<ReachGrid> reach;
  std::vector<GripperMatch> gripper;
  std::vector<std::string> problems;  ///< one line per failed check; empty = all passed
};

/// Runs every check. Throws antipode::Error for a scene file it cannot read and for options
/// out of range; a robot whose checks fail is reported in `problems`, not thrown.
RobotCheck check_robot(const RobotFile& robot, const RobotCheckOptions& options);

/// The gripper checks alone: the fingers (the links below `gripper_from` behind a prismatic
/// joint) at their joint limits, in the grasp frame, against the gripper file.
std::vector<GripperMatch> match_gripper(const RobotFile& robot, double tolerance_m);

/// The reach grids over the scene's box floor and the table around it.
std::vector<ReachGrid> reach_grids(const RobotFile& robot, const RobotCheckOptions& options);

}  // namespace antipode::collision
