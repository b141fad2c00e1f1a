#include "straight_approach.hpp"

#include <algorithm>
#include <cmath>

#include "antipode/robot/inverse_kinematics.hpp"

namespace antipode::planning {

std::optional<std::vector<Eigen::VectorXd>> straight_approach(
    const KinematicChain& arm, const collision::ArmCollisionWorld& world,
    const Eigen::Isometry3d& X_BaseHand, double distance_m, const Eigen::VectorXd& q_pregrasp,
    const ApproachOptions& options) {
  const int steps = std::max(1, int(std::ceil(distance_m / options.step_m)));
  const Eigen::Vector3d approach = X_BaseHand.linear().col(0);
  IkOptions ik;
  ik.max_iterations = 200;  // a nearby seed converges in a few iterations, or not at all
  std::vector<Eigen::VectorXd> states = {q_pregrasp};
  for (int k = 1; k <= steps; ++k) {
    Eigen::Isometry3d X = X_BaseHand;
    X.translation() -= approach * (distance_m * double(steps - k) / steps);
    const IkResult solved = solve_ik(arm, X, states.back(), ik);
    if (solved.solutions.empty()) return std::nullopt;
    const Eigen::VectorXd& q = solved.solutions.front();
    if ((q - states.back()).cwiseAbs().maxCoeff() > options.max_joint_step_rad) return std::nullopt;
    if (!world.check(q).free()) return std::nullopt;
    states.push_back(q);
  }
  return states;
}

}  // namespace antipode::planning
