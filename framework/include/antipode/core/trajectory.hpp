#pragma once
/// @file
/// Joint states and joint-space trajectories of a robot arm.
///
/// Units: radians for revolute joints (metres for prismatic ones), seconds from the
/// trajectory's start. Joints are named as in the robot's URDF.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace antipode {

/// The positions of named joints, e.g. the seven of Baxter's right arm.
struct JointState {
  std::vector<std::string> names;
  std::vector<double> positions_rad;  ///< one per name

  bool empty() const { return names.empty(); }
};

/// Joint-space waypoints, each with one position per joint, and the time each is reached.
/// Consecutive waypoints are joined by straight joint-space segments.
struct Trajectory {
  std::vector<std::string> joint_names;
  std::vector<std::vector<double>> positions_rad;  ///< [waypoint][joint]
  std::vector<double> times_s;                     ///< one per waypoint, non-decreasing

  bool empty() const { return positions_rad.empty(); }
};

/// Joint values as an Eigen vector (for kinematics) and back.
inline Eigen::VectorXd joint_vector(const std::vector<double>& q_rad) {
  return Eigen::Map<const Eigen::VectorXd>(q_rad.data(), Eigen::Index(q_rad.size()));
}
inline std::vector<double> joint_values(const Eigen::VectorXd& q_rad) {
  return {q_rad.data(), q_rad.data() + q_rad.size()};
}

}  // namespace antipode
