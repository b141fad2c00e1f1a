#pragma once
// The tip pose and the Jacobian of a KinematicChain in one pass, without allocating: the
// inner loop of the damped least-squares IK solver.
//
// Each segment moves its frame by a screw about (or along) its joint's axis, a line fixed
// in the segment's root frame: X_RootTip(q) = Screw(axis, origin, q) * X_RootTip(0). One pass
// down the chain composes these and keeps each moving joint's axis and point in the base
// frame; the Jacobian's columns follow from them (for a revolute joint: the axis z and
// z x (tip - point); for a prismatic one: z and zero).
//
// Why not orocos-kdl's solvers: ChainJntToJacSolver re-expresses the whole Jacobian at each
// segment (quadratic in the joints) and the IK step also ran the FK solver and sized Eigen's
// dynamic temporaries. An IK step with this pass costs 1.2 to 1.4 us on Baxter's arm, with
// KDL's solvers 3.0 to 3.8 us (collision_bench's BM_Ik_WholeBudget rows, runs apart on
// docs/results.md's machine). The
// answers agree with KDL's to rounding (the test compares them at random configurations of three
// arms).
//
// Frames and units: the chain's base frame; m and rad. The Jacobian maps joint velocities
// (rad/s, m/s) to the tip origin's linear velocity then the angular velocity, both in the
// base frame: orocos-kdl's convention, which pose_error() matches.
//
// Threads: const after construction; concurrent evaluations with their own outputs are safe.
// Each KinematicChain builds its evaluator once, when RobotModel::chain() makes it.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"

namespace KDL {
class Chain;
}

namespace antipode {

class ChainEvaluator {
 public:
  using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>;

  /// The description of `chain` (orocos-kdl's segments, joint scale 1 as RobotModel builds
  /// them) with its joints' `limits`. Reads the segments' poses at q = 0, which orocos-kdl
  /// caches in its joints: build it before the chain is shared between threads.
  ChainEvaluator(const KDL::Chain& chain, const std::vector<JointLimits>& limits);

  /// The evaluator `chain` was built with (an empty one for an empty chain).
  static const ChainEvaluator& of(const KinematicChain& chain);

  std::size_t dof() const { return dof_; }

  /// X_BaseTip at `q_rad` (dof() values, not checked) and the Jacobian into `J`, which is
  /// resized only when its size differs from 6 x dof().
  void evaluate(const Eigen::VectorXd& q_rad, Eigen::Isometry3d& X_BaseTip, Jacobian& J) const;

  /// False when no joint values put the tip at `X_BaseTip` within `margin_m`: the last
  /// joint's axis point, which the tip pose fixes (up to the last joint's stroke, if it
  /// slides), lies farther from the first joint's than the links between them span. True
  /// says nothing.
  bool may_reach(const Eigen::Isometry3d& X_BaseTip, double margin_m) const;

  /// The distance from the tip to the last joint's axis point (m): how far an orientation
  /// error of the tip moves that point.
  double lever_m() const { return p_TipLast_.norm(); }

 private:
  struct Segment {
    bool moves = false;
    bool prismatic = false;
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();    // unit, in the segment's root frame
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // a point on the axis, root frame
    Eigen::Isometry3d X_RootTip0 = Eigen::Isometry3d::Identity();  // the pose at q = 0
  };
  void set_reach_bound(const std::vector<JointLimits>& limits);

  std::vector<Segment> segments_;
  std::size_t dof_ = 0;
  // The reach bound: the first moving joint's axis point in the base frame, the last one's
  // in the tip frame, and the largest distance between them (infinite past a prismatic
  // joint without limits).
  Eigen::Vector3d p_BaseFirst_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_TipLast_ = Eigen::Vector3d::Zero();
  double span_m_ = 0.0;
};

}  // namespace antipode
