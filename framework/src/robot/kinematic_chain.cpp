#include "antipode/robot/kinematic_chain.hpp"

#include <cmath>
#include <string>
#include <utility>

#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/jacobian.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/segment.hpp>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "kinematic_chain_impl.hpp"

namespace antipode {

namespace {

KDL::JntArray to_kdl(const Eigen::VectorXd& q) {
  KDL::JntArray a(static_cast<unsigned>(q.size()));
  a.data = q;
  return a;
}

const KinematicChain::Impl& empty_impl() {
  static const KinematicChain::Impl impl;
  return impl;
}

}  // namespace

Eigen::Isometry3d to_eigen(const KDL::Frame& frame) {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    x.translation()(r) = frame.p(r);
    for (int c = 0; c < 3; ++c) x.linear()(r, c) = frame.M(r, c);
  }
  return x;
}

KDL::Frame to_kdl(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond r(pose.linear());
  const Eigen::Vector3d& t = pose.translation();
  return KDL::Frame(KDL::Rotation::Quaternion(r.x(), r.y(), r.z(), r.w()),
                    KDL::Vector(t.x(), t.y(), t.z()));
}

void check_joint_values(const KinematicChain& chain, const Eigen::VectorXd& q, const char* what) {
  if (static_cast<std::size_t>(q.size()) != chain.dof()) {
    throw Error(std::string(what) + ": " + std::to_string(q.size()) + " joint values for the " +
                std::to_string(chain.dof()) + " joints from '" + chain.base_link() + "' to '" +
                chain.tip_link() + "'");
  }
  if (!q.allFinite()) throw Error(std::string(what) + ": joint values must be finite");
}

KinematicChain::KinematicChain() = default;
KinematicChain::KinematicChain(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

const std::string& KinematicChain::base_link() const {
  return (impl_ ? *impl_ : empty_impl()).base_link;
}
const std::string& KinematicChain::tip_link() const {
  return (impl_ ? *impl_ : empty_impl()).tip_link;
}
const std::vector<std::string>& KinematicChain::joint_names() const {
  return (impl_ ? *impl_ : empty_impl()).joint_names;
}
const std::vector<JointLimits>& KinematicChain::limits() const {
  return (impl_ ? *impl_ : empty_impl()).limits;
}
std::size_t KinematicChain::dof() const { return limits().size(); }

Eigen::Isometry3d KinematicChain::forward(const Eigen::VectorXd& q) const {
  const std::vector<Eigen::Isometry3d> poses = link_poses(q);
  return poses.empty() ? Eigen::Isometry3d::Identity() : poses.back();
}

std::vector<std::string> KinematicChain::link_names() const {
  std::vector<std::string> names;
  if (!impl_) return names;
  for (unsigned i = 0; i < impl_->chain.getNrOfSegments(); ++i)
    names.push_back(impl_->chain.getSegment(i).getName());
  return names;
}

std::vector<Eigen::Isometry3d> KinematicChain::link_poses(const Eigen::VectorXd& q) const {
  check_joint_values(*this, q, "forward kinematics");
  std::vector<Eigen::Isometry3d> poses;
  if (!impl_) return poses;
  KDL::Frame frame = KDL::Frame::Identity();
  Eigen::Index joint = 0;
  for (unsigned i = 0; i < impl_->chain.getNrOfSegments(); ++i) {
    const KDL::Segment& segment = impl_->chain.getSegment(i);
    const bool moves = segment.getJoint().getType() != KDL::Joint::None;
    frame = frame * segment.pose(moves ? q(joint++) : 0.0);
    poses.push_back(to_eigen(frame));
  }
  return poses;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> KinematicChain::jacobian(const Eigen::VectorXd& q) const {
  check_joint_values(*this, q, "Jacobian");
  Eigen::Matrix<double, 6, Eigen::Dynamic> j(6, q.size());
  if (!impl_) return j;
  KDL::ChainJntToJacSolver solver(impl_->chain);
  KDL::Jacobian kdl_j(static_cast<unsigned>(q.size()));
  if (solver.JntToJac(to_kdl(q), kdl_j) < 0)
    throw InternalError("Jacobian failed for '" + tip_link() + "'");
  j = kdl_j.data;
  return j;
}

bool KinematicChain::within_limits(const Eigen::VectorXd& q, double tolerance) const {
  check_joint_values(*this, q, "joint limits");
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const JointLimits& l = limits()[static_cast<std::size_t>(i)];
    if (q(i) < l.lower - tolerance || q(i) > l.upper + tolerance) return false;
  }
  return true;
}

Eigen::VectorXd KinematicChain::mid_range() const {
  Eigen::VectorXd q(static_cast<Eigen::Index>(dof()));
  for (std::size_t i = 0; i < dof(); ++i)
    q(static_cast<Eigen::Index>(i)) = 0.5 * (limits()[i].lower + limits()[i].upper);
  return q;
}

Eigen::VectorXd KinematicChain::random_configuration(RandomStream& random) const {
  Eigen::VectorXd q(static_cast<Eigen::Index>(dof()));
  for (std::size_t i = 0; i < dof(); ++i) {
    const JointLimits& l = limits()[i];
    const double lo = std::isfinite(l.lower) ? l.lower : -M_PI;
    const double hi = std::isfinite(l.upper) ? l.upper : M_PI;
    q(static_cast<Eigen::Index>(i)) = random.uniform(lo, hi);
  }
  return q;
}

}  // namespace antipode
