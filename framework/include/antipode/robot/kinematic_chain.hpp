#pragma once
/// @file
/// A serial chain of a robot model, from a base link to a tip link: forward kinematics, the
/// geometric Jacobian and joint limits. Made by RobotModel::chain().
///
/// Units: metres, radians (prismatic joints: metres). `q` holds one value per moving joint
/// of the chain, base to tip, in the order of joint_names(). Poses are `X_BaseTip`: the tip
/// link's frame in the base link's frame.
///
/// Threads: a chain is immutable; every const member may be called concurrently. Copies
/// are cheap (they share the kinematic description).

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace antipode {

class RandomStream;

/// The range of one moving joint, from the URDF's <limit>.
struct JointLimits {
  double lower = 0.0;     ///< rad (m for prismatic joints)
  double upper = 0.0;     ///< rad (m for prismatic joints)
  double velocity = 0.0;  ///< rad/s (m/s)
};

class KinematicChain {
 public:
  /// An empty chain (no joints; forward() gives the identity).
  KinematicChain();

  const std::string& base_link() const;
  const std::string& tip_link() const;
  /// Moving joints, base to tip. Fixed joints are folded into the links' transforms.
  const std::vector<std::string>& joint_names() const;
  const std::vector<JointLimits>& limits() const;
  std::size_t dof() const;

  /// X_BaseTip at `q` (dof() values). Throws antipode::Error for a wrong size or a
  /// non-finite value; values outside the limits are evaluated as given.
  Eigen::Isometry3d forward(const Eigen::VectorXd& q) const;

  /// The links of the chain after the base, base to tip (the tip last).
  std::vector<std::string> link_names() const;
  /// X_BaseLink of every link of link_names() at `q`, in one pass. Throws like forward().
  std::vector<Eigen::Isometry3d> link_poses(const Eigen::VectorXd& q) const;

  /// The 6 x dof() geometric Jacobian at `q`, in the base frame, for the tip frame's origin:
  /// rows 0-2 linear velocity (m/s per unit joint rate), rows 3-5 angular velocity (rad/s).
  /// Throws like forward().
  Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian(const Eigen::VectorXd& q) const;

  /// True when every value lies in its joint's [lower - tolerance, upper + tolerance].
  bool within_limits(const Eigen::VectorXd& q, double tolerance = 0.0) const;
  /// The middle of every joint's range.
  Eigen::VectorXd mid_range() const;
  /// Joint values drawn uniformly within the limits from `random` (an unbounded joint in
  /// [-pi, pi)).
  Eigen::VectorXd random_configuration(RandomStream& random) const;

  struct Impl;  ///< the kinematic description (orocos-kdl), shared between copies

 private:
  friend class RobotModel;
  friend struct ChainAccess;  // the solvers' view of the description (framework only)
  explicit KinematicChain(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace antipode
