#include "screw_chain.hpp"

#include <cmath>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"

namespace antipode::collision {

namespace {

constexpr double kProbe = 1.0;       // how far each joint is moved to read its motion (rad or m)
constexpr double kMoves = 1e-9;      // a link that moves less than this did not move
constexpr double kAgreement = 1e-5;  // float forward kinematics against the chain's
constexpr double kAgreementDouble = 1e-9;  // the double one's

Eigen::VectorXd probe(std::size_t dof, int joint) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(Eigen::Index(dof));
  if (joint >= 0) q(joint) = kProbe;
  return q;
}

// X_{s-1}^-1 X_s for every link s of `poses` (the base before the first).
std::vector<Eigen::Isometry3d> relative(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Isometry3d> out;
  Eigen::Isometry3d parent = Eigen::Isometry3d::Identity();
  for (const Eigen::Isometry3d& X : poses) {
    out.push_back(parent.inverse() * X);
    parent = X;
  }
  return out;
}

double pose_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return std::max((a.translation() - b.translation()).norm(),
                  (a.linear() - b.linear()).cwiseAbs().maxCoeff());
}

Pose3f to_float(const Eigen::Isometry3d& X) {
  Pose3f p{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p.R[3 * i + j] = float(X.linear()(i, j));
    p.t[i] = float(X.translation()(i));
  }
  return p;
}

Eigen::Isometry3d to_double(const Pose3f& p) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) X.linear()(i, j) = p.R[3 * i + j];
    X.translation()(i) = p.t[i];
  }
  return X;
}

// a * b.
inline Pose3f compose(const Pose3f& a, const Pose3f& b) {
  Pose3f c;
  for (int i = 0; i < 3; ++i) {
    const float* r = a.R + 3 * std::ptrdiff_t(i);
    for (int j = 0; j < 3; ++j)
      c.R[3 * i + j] = r[0] * b.R[j] + r[1] * b.R[3 + j] + r[2] * b.R[6 + j];
    c.t[i] = r[0] * b.t[0] + r[1] * b.t[1] + r[2] * b.t[2] + a.t[i];
  }
  return c;
}

}  // namespace

ScrewChain::ScrewChain(const KinematicChain& arm) {
  const std::size_t dof = arm.dof();
  const std::vector<Eigen::Isometry3d> X0 = arm.link_poses(probe(dof, -1));  // X_BaseLink at 0
  const std::vector<Eigen::Isometry3d> at_zero = relative(X0);
  Eigen::Isometry3d X_BaseJoint0 = Eigen::Isometry3d::Identity();  // the current joint at 0
  int joint = -1;
  for (std::size_t s = 0; s < X0.size(); ++s) {
    const bool more = joint + 1 < int(dof);
    const Eigen::Isometry3d moved =
        more ? relative(arm.link_poses(probe(dof, joint + 1)))[s] : at_zero[s];
    const Eigen::Isometry3d J = moved * at_zero[s].inverse();  // the joint's motion, if any
    if (more && pose_error(J, Eigen::Isometry3d::Identity()) > kMoves) {
      ++joint;
      Joint next;
      const Eigen::AngleAxisd turn(J.linear());
      Eigen::Vector3d axis, point = Eigen::Vector3d::Zero();
      if (std::abs(turn.angle()) < kMoves) {
        next.prismatic = true;
        axis = J.translation() / kProbe;
      } else {
        axis = turn.axis() * (turn.angle() / kProbe);  // unit, signed by the motion
        // J's translation is (I - R) p for any point p on the axis: the nearest to the
        // origin solves it in the least-squares sense.
        const Eigen::Matrix3d A = Eigen::Matrix3d::Identity() - J.linear();
        point = A.completeOrthogonalDecomposition().solve(J.translation());
      }
      // The joint frame in the parent link's: z along the axis, origin on it.
      Eigen::Isometry3d X_ParentJoint = Eigen::Isometry3d::Identity();
      X_ParentJoint.linear() =
          Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
      X_ParentJoint.translation() = point;
      const Eigen::Isometry3d X_BaseParent0 = s == 0 ? Eigen::Isometry3d::Identity() : X0[s - 1];
      const Eigen::Isometry3d X_BaseNext0 = X_BaseParent0 * X_ParentJoint;
      next.C_d = X_BaseJoint0.inverse() * X_BaseNext0;
      next.C = to_float(next.C_d);
      X_BaseJoint0 = X_BaseNext0;
      joints_.push_back(next);
    }
    links_.push_back({joint, X_BaseJoint0.inverse() * X0[s]});
  }
  // The joint frames must reproduce the chain, in float and in double.
  bool agree = joints_.size() == dof;
  RandomStream random(7);
  std::vector<Pose3f> mine(dof);
  std::vector<Eigen::Isometry3d> mine_d(links_.size());
  for (int trial = 0; trial < 64 && agree; ++trial) {
    const Eigen::VectorXd q = arm.random_configuration(random);
    const std::vector<Eigen::Isometry3d> theirs = arm.link_poses(q);
    joint_poses(q.data(), mine.data());
    link_poses(q.data(), mine_d.data());
    for (std::size_t s = 0; s < theirs.size(); ++s) {
      const Link& link = links_[s];
      const Eigen::Isometry3d X_BaseJoint =
          link.joint < 0 ? Eigen::Isometry3d::Identity() : to_double(mine[std::size_t(link.joint)]);
      if (pose_error(X_BaseJoint * link.X_JointLink, theirs[s]) > kAgreement ||
          pose_error(mine_d[s], theirs[s]) > kAgreementDouble)
        agree = false;
    }
  }
  if (!agree)
    throw InternalError("screw chain: the joint axes read off '" + arm.tip_link() +
                        "' do not reproduce its forward kinematics");
}

void ScrewChain::joint_poses(const double* q_rad, Pose3f* X_BaseJoint) const {
  Pose3f X{{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}};
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    X = compose(X, joints_[j].C);
    const float q = float(reduced(j, q_rad[j]));
    if (joints_[j].prismatic) {
      for (int i = 0; i < 3; ++i) X.t[i] += q * X.R[3 * i + 2];  // X * Tz(q)
    } else {
      const float c = std::cos(q), s = std::sin(q);
      for (std::ptrdiff_t i = 0; i < 3; ++i) {  // X * Rz(q): the first two columns turn
        const float a = X.R[3 * i], b = X.R[3 * i + 1];
        X.R[3 * i] = c * a + s * b;
        X.R[3 * i + 1] = c * b - s * a;
      }
    }
    X_BaseJoint[j] = X;
  }
}

void ScrewChain::link_poses(const double* q_rad, Eigen::Isometry3d* X_BaseLink) const {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  int joint = -1;
  for (std::size_t s = 0; s < links_.size(); ++s) {
    while (joint < links_[s].joint) {  // the joints down to this link's
      const Joint& next = joints_[std::size_t(++joint)];
      X = X * next.C_d;
      const double q = q_rad[joint];
      if (next.prismatic) {
        X.translation() += q * X.linear().col(2);  // X * Tz(q)
      } else {
        const double c = std::cos(q), sn = std::sin(q);  // X * Rz(q): two columns turn
        const Eigen::Vector3d x = X.linear().col(0), y = X.linear().col(1);
        X.linear().col(0) = c * x + sn * y;
        X.linear().col(1) = c * y - sn * x;
      }
    }
    X_BaseLink[s] = X * links_[s].X_JointLink;
  }
}

}  // namespace antipode::collision
