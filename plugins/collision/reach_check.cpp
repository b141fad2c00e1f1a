#include "reach_check.hpp"

#include <algorithm>

#include "antipode/core/error.hpp"

namespace antipode::collision {

const char* to_string(ReachStatus status) {
  switch (status) {
    case ReachStatus::kReachable:
      return "reachable";
    case ReachStatus::kNoIkAtGrasp:
      return "no IK at the grasp";
    case ReachStatus::kInCollisionAtGrasp:
      return "arm in collision at the grasp";
    case ReachStatus::kNoIkAtPreGrasp:
      return "no IK at the pre-grasp";
    case ReachStatus::kInCollisionAtPreGrasp:
      return "arm in collision at the pre-grasp";
  }
  return "?";
}

Eigen::Isometry3d half_turned(const Eigen::Isometry3d& X_BaseHand) {
  Eigen::Isometry3d turned = X_BaseHand;
  turned.linear().col(1) *= -1.0;
  turned.linear().col(2) *= -1.0;
  return turned;
}

Reach check_reach(const KinematicChain& arm, const ArmCollisionWorld& world,
                  const Eigen::Isometry3d& X_BaseHand, const Eigen::VectorXd& q_seed,
                  const ReachOptions& options) {
  if (!(options.pregrasp_m >= 0.0) || options.grasp_solutions < 1)
    throw Error("reach check: pregrasp_m must be >= 0 and grasp_solutions at least 1");
  IkOptions at_grasp = options.ik;
  at_grasp.max_solutions = options.grasp_solutions;
  const IkResult grasp = solve_ik(arm, X_BaseHand, q_seed, at_grasp);
  Reach reach;
  if (grasp.status != IkStatus::kSolved) return reach;  // kNoIkAtGrasp
  Eigen::Isometry3d X_BasePreGrasp = X_BaseHand;
  X_BasePreGrasp.translation() -= options.pregrasp_m * X_BaseHand.linear().col(0);
  IkOptions at_pregrasp = options.ik;  // a long first descent: it starts near the answer
  at_pregrasp.max_solutions = options.grasp_solutions;
  at_pregrasp.iterations_per_descent = std::max(at_pregrasp.iterations_per_descent, 100);
  reach.status = ReachStatus::kInCollisionAtGrasp;
  for (const Eigen::VectorXd& q : grasp.solutions) {
    if (const ContactReport c = world.check(q); !c.free()) {
      if (reach.status == ReachStatus::kInCollisionAtGrasp && reach.detail.empty())
        reach.detail = c.str();
      continue;
    }
    IkResult pre = solve_ik(arm, X_BasePreGrasp, q, at_pregrasp);
    if (pre.status != IkStatus::kSolved) {
      if (reach.status == ReachStatus::kInCollisionAtGrasp)
        reach.status = ReachStatus::kNoIkAtPreGrasp, reach.detail.clear();
      continue;
    }
    // The free pre-grasp solution nearest the grasp one (the straight approach between them).
    std::sort(pre.solutions.begin(), pre.solutions.end(),
              [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
                return (a - q).squaredNorm() < (b - q).squaredNorm();
              });
    for (const Eigen::VectorXd& p : pre.solutions) {
      if (const ContactReport c = world.check(p); !c.free()) {
        reach.status = ReachStatus::kInCollisionAtPreGrasp;
        reach.detail = c.str();
        continue;
      }
      return {ReachStatus::kReachable, q, p, ""};
    }
  }
  return reach;
}

}  // namespace antipode::collision
