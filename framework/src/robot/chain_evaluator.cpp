#include "chain_evaluator.hpp"

#include <algorithm>
#include <cmath>

#include <kdl/segment.hpp>

#include "kinematic_chain_impl.hpp"

namespace antipode {

ChainEvaluator::ChainEvaluator(const KDL::Chain& chain, const std::vector<JointLimits>& limits) {
  for (const KDL::Segment& s : chain.segments) {
    const KDL::Joint& joint = s.getJoint();
    Segment segment;
    segment.moves = joint.getType() != KDL::Joint::None;
    segment.prismatic =
        joint.getType() == KDL::Joint::TransAxis || joint.getType() == KDL::Joint::TransX ||
        joint.getType() == KDL::Joint::TransY || joint.getType() == KDL::Joint::TransZ;
    if (segment.moves) {
      const KDL::Vector axis = joint.JointAxis();
      const KDL::Vector origin = joint.JointOrigin();
      segment.axis = Eigen::Vector3d(axis.x(), axis.y(), axis.z()).normalized();
      segment.origin = Eigen::Vector3d(origin.x(), origin.y(), origin.z());
      ++dof_;
    }
    segment.X_RootTip0 = to_eigen(s.pose(0.0));
    segments_.push_back(segment);
  }
  set_reach_bound(limits);
}

const ChainEvaluator& ChainEvaluator::of(const KinematicChain& chain) {
  static const ChainEvaluator empty(KDL::Chain(), {});
  const KinematicChain::Impl* impl = ChainAccess::of(chain);
  return impl != nullptr && impl->evaluator ? *impl->evaluator : empty;
}

// A revolute joint's axis point is fixed in the links on both sides of the joint (a turn
// about an axis leaves its points in place), so the distance between consecutive points is
// constant across a revolute joint, and changes by at most the stroke across a prismatic
// one (its point is fixed on its parent's side only). The triangle inequality bounds the
// first point's distance to the last by the sum.
void ChainEvaluator::set_reach_bound(const std::vector<JointLimits>& limits) {
  if (dof_ == 0) return;
  std::vector<Eigen::Vector3d> points;  // at q = 0, base frame
  Eigen::Isometry3d X_BaseTip = Eigen::Isometry3d::Identity();
  std::size_t joint = 0;
  for (const Segment& s : segments_) {
    if (s.moves) {
      points.push_back(X_BaseTip * s.origin);
      if (s.prismatic) {
        const JointLimits& l = limits[joint];
        span_m_ += std::max(std::abs(l.lower), std::abs(l.upper));
      }
      ++joint;
    }
    X_BaseTip = X_BaseTip * s.X_RootTip0;
  }
  for (std::size_t i = 1; i < points.size(); ++i) span_m_ += (points[i] - points[i - 1]).norm();
  p_BaseFirst_ = points.front();
  p_TipLast_ = X_BaseTip.inverse() * points.back();
}

bool ChainEvaluator::may_reach(const Eigen::Isometry3d& X_BaseTip, double margin_m) const {
  if (dof_ == 0) return true;
  return (X_BaseTip * p_TipLast_ - p_BaseFirst_).norm() <= span_m_ + margin_m;
}

void ChainEvaluator::evaluate(const Eigen::VectorXd& q_rad, Eigen::Isometry3d& X_BaseTip,
                              Jacobian& J) const {
  const auto n = static_cast<Eigen::Index>(dof_);
  if (J.cols() != n) J.resize(6, n);
  // The pose so far as a rotation and a translation (Eigen's Isometry3d product is a
  // 4 x 4 one). During the pass the linear rows hold each revolute joint's point; the cross
  // products with the tip follow once the tip is known.
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Index j = 0;
  for (const Segment& s : segments_) {
    const Eigen::Matrix3d& R0 = s.X_RootTip0.linear();
    const Eigen::Vector3d t0 = s.X_RootTip0.translation();
    if (!s.moves) {
      t += R * t0;
      R = (R * R0).eval();
      continue;
    }
    const Eigen::Vector3d z = R * s.axis;
    const double q = q_rad(j);
    if (s.prismatic) {
      J.col(j) << z, Eigen::Vector3d::Zero();
      t += R * (t0 + q * s.axis);
      R = (R * R0).eval();
    } else {
      J.col(j) << R * s.origin + t, z;
      // The turn by q about the axis through the origin: Rq, and origin - Rq origin.
      const Eigen::Matrix3d Rq = Eigen::AngleAxisd(q, s.axis).toRotationMatrix();
      t += R * (Rq * (t0 - s.origin) + s.origin);
      R = (R * (Rq * R0)).eval();
    }
    ++j;
  }
  X_BaseTip.linear() = R;
  X_BaseTip.translation() = t;
  X_BaseTip.makeAffine();
  j = 0;
  for (const Segment& s : segments_) {
    if (!s.moves) continue;
    if (!s.prismatic) {
      const Eigen::Vector3d point = J.col(j).head<3>();
      J.col(j).head<3>() = J.col(j).tail<3>().cross(t - point);
    }
    ++j;
  }
}

}  // namespace antipode
