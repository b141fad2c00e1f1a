#include "reach_check.hpp"

#include <algorithm>
#include <optional>
#include <string>

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

namespace {

// The pre-grasp pose: `X_BaseHand` moved back along its approach.
Eigen::Isometry3d pregrasp_of(const Eigen::Isometry3d& X_BaseHand, double pregrasp_m) {
  Eigen::Isometry3d X_BasePreGrasp = X_BaseHand;
  X_BasePreGrasp.translation() -= pregrasp_m * X_BaseHand.linear().col(0);
  return X_BasePreGrasp;
}

// A free pre-grasp solution for the free grasp solution `q`, chosen as `options.search`
// says; none when there is none, with `reach`'s status and detail saying why.
std::optional<Eigen::VectorXd> free_pregrasp(const KinematicChain& arm,
                                             const ArmCollisionWorld& world,
                                             const Eigen::Isometry3d& X_BasePreGrasp,
                                             const Eigen::VectorXd& q, const ReachOptions& options,
                                             Reach& reach) {
  IkOptions at_pregrasp = options.ik;  // a long first descent: it starts near the answer
  at_pregrasp.max_solutions = options.grasp_solutions;
  at_pregrasp.iterations_per_descent = std::max(at_pregrasp.iterations_per_descent, 100);
  std::optional<Eigen::VectorXd> found;
  const auto free = [&](const Eigen::VectorXd& p) {
    if (const ContactReport c = world.check(p); !c.free()) {
      reach.status = ReachStatus::kInCollisionAtPreGrasp;
      reach.detail = c.str();
      return false;
    }
    found = p;
    return true;
  };
  IkResult pre;
  if (options.search == ReachSearch::kFirstFree) {
    pre = solve_ik(arm, X_BasePreGrasp, q, at_pregrasp,
                   [&](const Eigen::VectorXd& p) { return !free(p); });
  } else {
    pre = solve_ik(arm, X_BasePreGrasp, q, at_pregrasp);
    // The free solution nearest the grasp one (the straight approach between them).
    std::sort(pre.solutions.begin(), pre.solutions.end(),
              [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
                return (a - q).squaredNorm() < (b - q).squaredNorm();
              });
    for (const Eigen::VectorXd& p : pre.solutions)
      if (free(p)) break;
  }
  if (pre.status != IkStatus::kSolved && reach.status == ReachStatus::kInCollisionAtGrasp) {
    reach.status = ReachStatus::kNoIkAtPreGrasp;
    reach.detail.clear();
  }
  return found;
}

// What solve_ik refuses, refused before the hand's check so that every search throws alike.
void check_ik_inputs(const KinematicChain& arm, const Eigen::Isometry3d& X_BaseHand,
                     const Eigen::VectorXd& q_seed, const IkOptions& ik) {
  ik.validate();
  if (static_cast<std::size_t>(q_seed.size()) != arm.dof() || !q_seed.allFinite() ||
      !arm.within_limits(q_seed, 1e-9))
    throw Error("IK seed: " + std::to_string(arm.dof()) +
                " finite joint values within the limits are needed");
  const Eigen::Matrix3d r = X_BaseHand.linear();
  if (!X_BaseHand.matrix().allFinite() ||
      !(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-6) || r.determinant() < 0)
    throw Error("IK target: not a finite rigid transform");
}

// Whether the hand alone - the links rigid with the arm's tip - meets the scene at the grasp
// or at the pre-grasp: then every IK solution there is in collision, and none need be solved.
std::optional<Reach> hand_in_contact(const ArmCollisionWorld& world,
                                     const Eigen::Isometry3d& X_BaseHand,
                                     const Eigen::Isometry3d& X_BasePreGrasp) {
  if (const ContactReport c = world.check_tip_links(X_BaseHand); !c.free())
    return Reach{ReachStatus::kInCollisionAtGrasp, {}, {}, c.str()};
  if (const ContactReport c = world.check_tip_links(X_BasePreGrasp); !c.free())
    return Reach{ReachStatus::kInCollisionAtPreGrasp, {}, {}, c.str()};
  return std::nullopt;
}

}  // namespace

const char* to_string(ReachSearch search) {
  switch (search) {
    case ReachSearch::kFirstFree:
      return "first_free";
    case ReachSearch::kNearestPreGrasp:
      return "nearest_pregrasp";
    case ReachSearch::kExhaustive:
      return "exhaustive";
  }
  return "?";
}

ReachSearch reach_search(const std::string& name) {
  for (ReachSearch s :
       {ReachSearch::kFirstFree, ReachSearch::kNearestPreGrasp, ReachSearch::kExhaustive})
    if (name == to_string(s)) return s;
  throw Error("unknown reach search '" + name + "'" +
              did_you_mean(name, {"first_free", "nearest_pregrasp", "exhaustive"}) +
              " (use first_free, nearest_pregrasp or exhaustive)");
}

Reach check_reach(const KinematicChain& arm, const ArmCollisionWorld& world,
                  const Eigen::Isometry3d& X_BaseHand, const Eigen::VectorXd& q_seed,
                  const ReachOptions& options) {
  if (!(options.pregrasp_m >= 0.0) || options.grasp_solutions < 1)
    throw Error("reach check: pregrasp_m must be >= 0 and grasp_solutions at least 1");
  const Eigen::Isometry3d X_BasePreGrasp = pregrasp_of(X_BaseHand, options.pregrasp_m);
  const bool exhaustive = options.search == ReachSearch::kExhaustive;
  check_ik_inputs(arm, X_BaseHand, q_seed, options.ik);
  if (!exhaustive)
    if (auto contact = hand_in_contact(world, X_BaseHand, X_BasePreGrasp)) return *contact;
  Reach reach;  // kNoIkAtGrasp until a solution is found
  // One grasp solution: whether to search on.
  const auto try_grasp = [&](const Eigen::VectorXd& q) {
    if (reach.status == ReachStatus::kNoIkAtGrasp) reach.status = ReachStatus::kInCollisionAtGrasp;
    if (const ContactReport c = world.check(q); !c.free()) {
      if (reach.status == ReachStatus::kInCollisionAtGrasp && reach.detail.empty())
        reach.detail = c.str();
      return true;
    }
    if (auto p = free_pregrasp(arm, world, X_BasePreGrasp, q, options, reach)) {
      reach = {ReachStatus::kReachable, q, std::move(*p), ""};
      return false;
    }
    return true;
  };
  IkOptions at_grasp = options.ik;
  at_grasp.max_solutions = options.grasp_solutions;
  if (!exhaustive) {
    solve_ik(arm, X_BaseHand, q_seed, at_grasp, try_grasp);
    return reach;
  }
  // The baseline solves first and asks about the hand last; the hand's answer stands, as in
  // the other searches (it differs from the IK's only for a contact within IK's tolerance).
  for (const Eigen::VectorXd& q : solve_ik(arm, X_BaseHand, q_seed, at_grasp).solutions)
    if (!try_grasp(q)) break;
  if (auto contact = hand_in_contact(world, X_BaseHand, X_BasePreGrasp)) return *contact;
  return reach;
}

}  // namespace antipode::collision
