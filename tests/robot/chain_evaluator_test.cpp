// The IK solver's one-pass tip pose and Jacobian against the chain's own forward kinematics
// and Jacobian (orocos-kdl's solvers), on three arms, a chain with a prismatic joint and
// chains shorter than six joints.

#include <string>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"
#include "chain_evaluator.hpp"

namespace antipode {
namespace {

const std::string kRobots = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/";

struct ChainCase {
  std::string urdf;
  std::string base;
  std::string tip;
  std::size_t dof;
};

std::vector<ChainCase> chains() {
  return {{"baxter/baxter.urdf", "base", "right_gripper", 7},
          {"baxter/baxter.urdf", "right_gripper_base", "right_gripper_l_finger", 1},
          {"baxter/baxter.urdf", "base", "right_lower_elbow", 4},
          {"panda/panda.urdf", "base", "panda_leftfinger", 8},
          {"ur5e/ur5e.urdf", "base", "ur5e_hand", 6}};
}

KinematicChain load(const ChainCase& c) {
  return RobotModel::load(kRobots + c.urdf).chain(c.base, c.tip);
}

TEST(ChainEvaluator, AgreesWithTheChainsForwardKinematicsAndJacobian) {
  for (const ChainCase& c : chains()) {
    const KinematicChain chain = load(c);
    ASSERT_EQ(chain.dof(), c.dof) << c.tip;
    const ChainEvaluator& kin = ChainEvaluator::of(chain);
    ASSERT_EQ(kin.dof(), c.dof) << c.tip;
    RandomStream random(11);
    ChainEvaluator::Jacobian J;
    for (int i = 0; i < 100; ++i) {
      const Eigen::VectorXd q = chain.random_configuration(random);
      Eigen::Isometry3d X_BaseTip;
      kin.evaluate(q, X_BaseTip, J);
      EXPECT_LT((X_BaseTip.matrix() - chain.forward(q).matrix()).cwiseAbs().maxCoeff(), 1e-12)
          << c.tip << " at configuration " << i;
      EXPECT_LT((J - chain.jacobian(q)).cwiseAbs().maxCoeff(), 1e-12)
          << c.tip << " at configuration " << i;
    }
  }
}

// The reach bound never refuses a pose the chain takes, and refuses one moved past it.
TEST(ChainEvaluator, TheReachBoundHoldsEveryReachablePose) {
  for (const ChainCase& c : chains()) {
    const KinematicChain chain = load(c);
    const ChainEvaluator& kin = ChainEvaluator::of(chain);
    RandomStream random(13);
    for (int i = 0; i < 1000; ++i) {
      const Eigen::VectorXd q = chain.random_configuration(random);
      ASSERT_TRUE(kin.may_reach(chain.forward(q), 1e-9)) << c.tip << " at configuration " << i;
    }
    Eigen::Isometry3d far = chain.forward(chain.mid_range());
    far.translation() += Eigen::Vector3d(0.0, 0.0, 5.0);
    EXPECT_FALSE(kin.may_reach(far, 1e-3)) << c.tip;
  }
}

// The damped step factors J^T J for chains of fewer than six joints and J J^T from six on:
// both solve poses the chain reaches, with the one-pass kinematics and with orocos-kdl's.
TEST(ChainEvaluator, IkSolvesReachablePosesOfShortAndLongChains) {
  for (const ChainCase& c : chains())
    for (const IkSolver solver :
         {IkSolver::kDampedLeastSquares, IkSolver::kDampedLeastSquaresKdl}) {
      SCOPED_TRACE(to_string(solver));
      const KinematicChain chain = load(c);
      RandomStream random(5);
      int solved = 0;
      for (int i = 0; i < 20; ++i) {
        const Eigen::Isometry3d target = chain.forward(chain.random_configuration(random));
        IkOptions options;
        options.solver = solver;
        options.seed = static_cast<std::uint64_t>(i);
        const IkResult r = solve_ik(chain, target, chain.mid_range(), options);
        if (r.status != IkStatus::kSolved) continue;
        ++solved;
        EXPECT_LE(pose_error(target, chain.forward(r.solutions[0])).cwiseAbs().maxCoeff(), 1e-5);
      }
      EXPECT_GE(solved, 18) << c.tip;  // 90%: the default budget, random poses
    }
}

}  // namespace
}  // namespace antipode
