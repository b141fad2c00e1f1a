// Inverse kinematics of Baxter's right arm: round trips from random reachable poses, distinct
// solutions, joint limits, determinism and input errors.

#include <string>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"
#include "support/error_of.hpp"

namespace antipode {
namespace {

using testing::error_of;

KinematicChain right_arm() {
  static const RobotModel robot =
      RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf");
  return robot.chain("base", "right_gripper");
}

TEST(InverseKinematics, PoseErrorIsZeroAtTheTargetAndMeasuresOffsets) {
  Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
  a.translate(Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_LT(pose_error(a, a).norm(), 1e-15);
  Eigen::Isometry3d b = a;
  b.translation().x() += 0.01;
  b.prerotate(Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()));
  const auto e = pose_error(a, b);
  EXPECT_NEAR(e.tail<3>().norm(), 0.2, 1e-12);
  EXPECT_NEAR(e.tail<3>().z(), -0.2, 1e-12);
}

TEST(InverseKinematics, RoundTripsOnRandomReachablePoses) {
  const KinematicChain arm = right_arm();
  RandomStream random(7);
  int solved = 0;
  const int poses = 200;
  for (int i = 0; i < poses; ++i) {
    const Eigen::Isometry3d target = arm.forward(arm.random_configuration(random));
    IkOptions options;
    options.seed = static_cast<std::uint64_t>(i);
    const IkResult r = solve_ik(arm, target, arm.mid_range(), options);
    if (r.status != IkStatus::kSolved) continue;
    ++solved;
    ASSERT_EQ(r.solutions.size(), 1u);
    EXPECT_TRUE(arm.within_limits(r.solutions[0]));
    EXPECT_LE(pose_error(target, arm.forward(r.solutions[0])).cwiseAbs().maxCoeff(), 1e-5);
  }
  EXPECT_GE(solved, poses * 98 / 100);
}

// Options that ask for `solutions` solutions with a budget large enough to find them.
IkOptions several(int solutions, std::uint64_t seed = 0) {
  IkOptions options;
  options.max_solutions = solutions;
  options.max_iterations = 20000;
  options.seed = seed;
  return options;
}

TEST(InverseKinematics, FindsSeveralDistinctSolutionsOnRequest) {
  const KinematicChain arm = right_arm();
  RandomStream random(11);
  const Eigen::Isometry3d target = arm.forward(arm.random_configuration(random));
  const IkOptions options = several(4);
  const IkResult r = solve_ik(arm, target, arm.mid_range(), options);
  ASSERT_EQ(r.status, IkStatus::kSolved);
  ASSERT_EQ(r.solutions.size(), 4u);  // a 7-joint arm has a continuum of them
  for (std::size_t a = 0; a < r.solutions.size(); ++a) {
    EXPECT_LE(pose_error(target, arm.forward(r.solutions[a])).cwiseAbs().maxCoeff(), 1e-5);
    for (std::size_t b = 0; b < a; ++b)
      EXPECT_GE((r.solutions[a] - r.solutions[b]).cwiseAbs().maxCoeff(), options.distinct);
  }
}

TEST(InverseKinematics, SameSeedSameSolution) {
  const KinematicChain arm = right_arm();
  RandomStream random(3);
  const Eigen::Isometry3d target = arm.forward(arm.random_configuration(random));
  const IkOptions options = several(2, 42);
  const IkResult a = solve_ik(arm, target, arm.mid_range(), options);
  const IkResult b = solve_ik(arm, target, arm.mid_range(), options);
  ASSERT_EQ(a.solutions.size(), b.solutions.size());
  for (std::size_t i = 0; i < a.solutions.size(); ++i) EXPECT_EQ(a.solutions[i], b.solutions[i]);
  EXPECT_EQ(a.iterations, b.iterations);
}

// The visitor sees the solutions solve_ik returns, in its order, and stopping it early
// leaves the first ones found and spends fewer iterations.
TEST(InverseKinematics, TheVisitorSeesTheSolutionsAsFoundAndCanStopTheSearch) {
  const KinematicChain arm = right_arm();
  RandomStream random(5);
  const Eigen::Isometry3d target = arm.forward(arm.random_configuration(random));
  const IkOptions options = several(5, 7);
  const IkResult all = solve_ik(arm, target, arm.mid_range(), options);
  ASSERT_EQ(all.solutions.size(), 5u);
  std::vector<Eigen::VectorXd> seen;
  const IkResult visited =
      solve_ik(arm, target, arm.mid_range(), options, [&](const Eigen::VectorXd& q) {
        seen.push_back(q);
        return true;
      });
  EXPECT_EQ(seen, all.solutions);
  EXPECT_EQ(visited.solutions, all.solutions);
  EXPECT_EQ(visited.iterations, all.iterations);
  const IkResult first_two = solve_ik(arm, target, arm.mid_range(), options,
                                      [n = 0](const Eigen::VectorXd&) mutable { return ++n < 2; });
  ASSERT_EQ(first_two.status, IkStatus::kSolved);
  ASSERT_EQ(first_two.solutions.size(), 2u);
  EXPECT_EQ(first_two.solutions[0], all.solutions[0]);
  EXPECT_EQ(first_two.solutions[1], all.solutions[1]);
  EXPECT_LT(first_two.iterations, all.iterations);
}

TEST(InverseKinematics, AnUnreachablePoseHasNoSolution) {
  const KinematicChain arm = right_arm();
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(3.0, 0.0, 0.0);  // beyond the arm's 1.3 m reach
  // The one-pass kinematics' reach bound refuses it without a step; orocos-kdl's
  // kinematics (the baseline) spend the whole budget on it.
  const IkResult r = solve_ik(arm, far, arm.mid_range());
  EXPECT_EQ(r.status, IkStatus::kNoSolution);
  EXPECT_TRUE(r.solutions.empty());
  EXPECT_EQ(r.iterations, 0);
  IkOptions kdl;
  kdl.solver = IkSolver::kDampedLeastSquaresKdl;
  const IkResult searched = solve_ik(arm, far, arm.mid_range(), kdl);
  EXPECT_EQ(searched.status, IkStatus::kNoSolution);
  EXPECT_EQ(searched.iterations, kdl.max_iterations);
}

TEST(InverseKinematics, KdlBaselineSolvesFromANearbySeed) {
  const KinematicChain arm = right_arm();
  const Eigen::VectorXd q = arm.mid_range() + Eigen::VectorXd::Constant(7, 0.05);
  IkOptions options;
  options.solver = IkSolver::kKdl;
  const IkResult r = solve_ik(arm, arm.forward(q), arm.mid_range(), options);
  ASSERT_EQ(r.status, IkStatus::kSolved);
  EXPECT_LE(pose_error(arm.forward(q), arm.forward(r.solutions[0])).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(InverseKinematics, BadInputIsAnError) {
  const KinematicChain arm = right_arm();
  const Eigen::Isometry3d target = arm.forward(arm.mid_range());
  EXPECT_NE(error_of([&] {
              solve_ik(arm, target, Eigen::VectorXd::Zero(3));
            }).find("IK seed: 3 joint values for the 7 joints"),
            std::string::npos);
  Eigen::VectorXd outside = arm.mid_range();
  outside(3) = 3.0;  // e1 stops at 2.618
  EXPECT_NE(error_of([&] { solve_ik(arm, target, outside); }).find("outside the limits"),
            std::string::npos);
  Eigen::Isometry3d sheared = target;
  sheared.linear()(0, 1) += 0.5;
  EXPECT_NE(error_of([&] { solve_ik(arm, sheared, arm.mid_range()); }).find("rigid transform"),
            std::string::npos);
  IkOptions bad;
  bad.max_solutions = 0;
  EXPECT_NE(error_of([&] {
              solve_ik(arm, target, arm.mid_range(), bad);
            }).find("max_solutions must be at least 1"),
            std::string::npos);
  EXPECT_NE(error_of([] { ik_solver("trac"); }).find("unknown IK solver 'trac'"),
            std::string::npos);
  EXPECT_EQ(error_of([] { ik_solver("dls-kdl"); }),
            "unknown IK solver 'dls-kdl' (did you mean 'dls_kdl'?) (use dls, kdl or dls_kdl)");
  for (const IkSolver s :
       {IkSolver::kDampedLeastSquares, IkSolver::kKdl, IkSolver::kDampedLeastSquaresKdl})
    EXPECT_EQ(ik_solver(to_string(s)), s);
}

}  // namespace
}  // namespace antipode
