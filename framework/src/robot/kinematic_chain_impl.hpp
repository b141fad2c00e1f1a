#pragma once
// The shared description behind KinematicChain: an orocos-kdl chain (fixed joints folded
// into segments) with its names and limits.

#include <memory>
#include <string>
#include <vector>

#include <kdl/chain.hpp>
#include <kdl/frames.hpp>

#include "antipode/robot/kinematic_chain.hpp"
#include "chain_evaluator.hpp"

namespace antipode {

struct KinematicChain::Impl {
  std::string base_link;
  std::string tip_link;
  std::vector<std::string> joint_names;
  std::vector<JointLimits> limits;
  KDL::Chain chain;
  /// The IK's kinematics of `chain`, built once the chain is complete (RobotModel::chain).
  std::shared_ptr<const ChainEvaluator> evaluator;
};

/// The description of a chain, for the kinematics solvers; nullptr for an empty chain.
struct ChainAccess {
  static const KinematicChain::Impl* of(const KinematicChain& chain) { return chain.impl_.get(); }
};

/// The same rigid transform in Eigen's and in KDL's types.
Eigen::Isometry3d to_eigen(const KDL::Frame& frame);
KDL::Frame to_kdl(const Eigen::Isometry3d& pose);

/// Throws antipode::Error unless `q` has `chain.dof()` finite values; `what` names the
/// caller in the message.
void check_joint_values(const KinematicChain& chain, const Eigen::VectorXd& q, const char* what);

}  // namespace antipode
