#pragma once
// The robot arm of the simulated cell: it starts every attempt at its home configuration,
// follows a joint-space trajectory kinematically (no dynamics), and reports the first
// contact of one of its links with the true scene - the table, the box, the objects - on
// the way ("collision with the environment", the paper's failure class). Its links on the
// chain to the grasp frame are checked (a hand's housing too); the fingers, off the chain,
// are not: the cell's gripper simulation takes over at the end of the trajectory.
//
// Frames and units: the robot's base frame is the cell's base frame; radians, metres.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/error.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/robot/robot_model.hpp"
#include "physics_world.hpp"

class btCollisionShape;

namespace antipode::cells {

struct CellArmOptions {
  std::string robot_file;        ///< the URDF
  std::string tip;               ///< the arm chain's tip (the grasp frame)
  std::vector<double> home_rad;  ///< where every attempt starts, one value per joint
  double check_step_rad = 0.02;  ///< largest joint change between checked states
};

/// Where a trajectory first touched the scene.
struct ArmContact {
  std::string link;         ///< the arm's link
  std::string body;         ///< the scene body it touched
  std::size_t segment = 0;  ///< the trajectory segment (waypoint index before the contact)
};

class CellArm {
 public:
  /// The home configuration does not suit the arm (`home_rad`'s fault, not the robot's).
  class HomeError : public Error {
   public:
    using Error::Error;
  };

  /// Throws antipode::Error for an unreadable URDF or an unknown link, and HomeError for a
  /// home configuration of the wrong size or outside the joint limits.
  explicit CellArm(const CellArmOptions& options);
  ~CellArm();
  CellArm(CellArm&&) noexcept;
  CellArm& operator=(CellArm&&) noexcept;

  JointState home() const;
  const std::vector<std::string>& joint_names() const;

  /// "" when `trajectory` can be followed by this arm, else why not (other joints, wrong
  /// sizes, not finite, outside the limits, not starting at home).
  std::string check_trajectory(const Trajectory& trajectory) const;
  /// The first contact of a checked link with a body of `world` along the trajectory
  /// (states every check_step_rad), or none.
  std::optional<ArmContact> first_contact(const Trajectory& trajectory,
                                          const PhysicsWorld& world) const;
  /// X_BaseTip at the trajectory's end.
  Eigen::Isometry3d tip_pose(const std::vector<double>& q_rad) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace antipode::cells
