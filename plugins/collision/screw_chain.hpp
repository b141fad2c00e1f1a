#pragma once
// Forward kinematics of a KinematicChain without allocation, in the frames of its joints:
// joint j's frame has its z axis on the joint's axis and turns (or slides) with it, so that
// X_BaseJoint_j = X_BaseJoint_{j-1} * C_j * Rz(q_j) (or * Tz(q_j)) with C_j constant. That is
// one full product and one rotation about z per joint, with the chain's fixed joints folded
// into the constants. Every link of the chain hangs from the joint frame before it by a
// constant X_JointLink (links before the first joint from the base). In float for the sphere
// tests (joint_poses), in double for placing FCL's shapes (link_poses).
//
// The joints' axes are read off the chain itself (its link poses with one joint moved at a
// time), so this agrees with KinematicChain::link_poses() for any URDF the chain accepts; the
// constructor checks that at random configurations: to 1e-5 m and rad in float (rounding over
// a chain of a metre or two), to 1e-9 in double.
//
// Why not KinematicChain::link_poses(): it goes through orocos-kdl and returns a new vector
// per call (0.4 us for Baxter's arm); the collision checks need the arm's pose millions of
// times a second.
//
// Frames and units as KinematicChain: metres, radians. Threads: immutable after
// construction; joint_poses() and link_poses() may run concurrently.

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"

namespace antipode::collision {

/// A rigid transform in float: rotation R (row by row) and translation t.
struct Pose3f {
  float R[9];
  float t[3];
};

class ScrewChain {
 public:
  /// Throws antipode::InternalError when the axes read off `arm` do not reproduce its link
  /// poses.
  explicit ScrewChain(const KinematicChain& arm);

  std::size_t dof() const { return joints_.size(); }

  /// X_BaseJoint of every joint frame at `q_rad` (dof() values) into `X_BaseJoint`.
  void joint_poses(const double* q_rad, Pose3f* X_BaseJoint) const;

  /// The same kinematics in double, for the exact checks: X_BaseLink of every link of
  /// KinematicChain::link_names() at `q_rad` into `X_BaseLink` (links() of them), without
  /// allocating. Agrees with KinematicChain::link_poses() to rounding (the constructor checks
  /// it to 1e-9).
  void link_poses(const double* q_rad, Eigen::Isometry3d* X_BaseLink) const;
  std::size_t links() const { return links_.size(); }

  /// The joint frame link `link` of KinematicChain::link_names() hangs from (-1: the base),
  /// and the pose of the link in it.
  int joint_of(std::size_t link) const { return links_[link].joint; }
  /// q_rad for joint j as the float kinematics take it: a revolute joint's angle reduced to
  /// [-pi, pi] in double (float keeps a large angle too coarsely), a prismatic joint's as is.
  double reduced(std::size_t j, double q_rad) const {
    return joints_[j].prismatic || std::abs(q_rad) <= M_PI ? q_rad
                                                           : std::remainder(q_rad, 2.0 * M_PI);
  }
  /// Joint j's frame at q = 0 in joint j - 1's (or the base's), and whether it slides.
  const Pose3f& constant(std::size_t j) const { return joints_[j].C; }
  bool prismatic(std::size_t j) const { return joints_[j].prismatic; }
  const Eigen::Isometry3d& X_JointLink(std::size_t link) const { return links_[link].X_JointLink; }

 private:
  struct Joint {
    bool prismatic = false;
    Pose3f C{};  // the joint frame at q = 0 in the previous joint's frame (or the base)
    Eigen::Isometry3d C_d = Eigen::Isometry3d::Identity();  // the same in double
  };
  struct Link {
    int joint = -1;
    Eigen::Isometry3d X_JointLink = Eigen::Isometry3d::Identity();
  };
  std::vector<Joint> joints_;
  std::vector<Link> links_;
};

}  // namespace antipode::collision
