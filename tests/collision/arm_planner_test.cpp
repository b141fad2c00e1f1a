// OMPL arm planning for Baxter's right arm: paths that avoid a box blocking the straight
// motion (checked densely along the path), invalid starts and goals, errors.

#include <string>

#include <gtest/gtest.h>

#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "arm_planner.hpp"
#include "support/error_of.hpp"

namespace antipode::planning {
namespace {

using collision::ArmCollisionWorld;
using testing::error_of;

struct Baxter {
  RobotModel robot =
      RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf");
  KinematicChain arm = robot.chain("base", "right_gripper");
  ArmCollisionWorld world{robot, arm};
};

Eigen::VectorXd q7(double s0, double s1, double e0, double e1, double w0, double w1, double w2) {
  Eigen::VectorXd q(7);
  q << s0, s1, e0, e1, w0, w1, w2;
  return q;
}

const Eigen::VectorXd kNeutral = q7(0, -0.55, 0, 0.75, 0, 1.26, 0);
const Eigen::VectorXd kReach = q7(-0.8, -0.3, 0.4, 1.2, -0.3, 0.9, 0.2);

ArmPlanningProblem problem(const Baxter& b, std::uint64_t seed = 1) {
  ArmPlanningProblem p;
  p.arm = &b.arm;
  p.world = &b.world;
  p.start = kNeutral;
  p.goal = kReach;
  p.seed = seed;
  p.time_limit_s = 5.0;
  return p;
}

// A 12 cm box where the gripper passes halfway along the straight joint-space motion.
void block_the_straight_motion(Baxter& b) {
  Eigen::Isometry3d X_BaseBox = Eigen::Isometry3d::Identity();
  X_BaseBox.translation() = b.arm.forward(0.5 * (kNeutral + kReach)).translation();
  b.world.add_box("obstacle", X_BaseBox, Eigen::Vector3d(0.12, 0.12, 0.12));
}

// Every path segment free when checked at a quarter of the planning resolution.
void expect_free_path(const Baxter& b, const ArmPlan& plan, double resolution_rad) {
  ASSERT_GE(plan.path.size(), 2u);
  for (std::size_t i = 0; i + 1 < plan.path.size(); ++i) {
    EXPECT_TRUE(segment_is_free(b.world, plan.path[i], plan.path[i + 1], resolution_rad / 4))
        << "segment " << i;
  }
}

TEST(ArmPlanner, PlansAroundABoxThatBlocksTheStraightMotion) {
  Baxter b;
  ASSERT_TRUE(segment_is_free(b.world, kNeutral, kReach, 0.005));
  block_the_straight_motion(b);
  ASSERT_FALSE(segment_is_free(b.world, kNeutral, kReach, 0.005));
  const ArmPlanningProblem p = problem(b);
  const ArmPlan plan = plan_arm_motion(p);
  ASSERT_EQ(plan.status, PlanStatus::kSolved) << to_string(plan.status);
  EXPECT_EQ(plan.path.front(), kNeutral);
  EXPECT_EQ(plan.path.back(), kReach);
  EXPECT_GE(plan.path.size(), 3u);  // the straight motion is blocked
  expect_free_path(b, plan, p.resolution_rad);
}

TEST(ArmPlanner, TheSameSeedGivesTheSamePath) {
  Baxter b;
  block_the_straight_motion(b);
  const ArmPlan first = plan_arm_motion(problem(b, 7));
  const ArmPlan second = plan_arm_motion(problem(b, 7));
  ASSERT_EQ(first.status, PlanStatus::kSolved);
  ASSERT_EQ(first.path.size(), second.path.size());
  for (std::size_t i = 0; i < first.path.size(); ++i) EXPECT_EQ(first.path[i], second.path[i]);
}

TEST(ArmPlanner, AnInvalidStartOrGoalIsAStatusWithTheContact) {
  Baxter b;
  ArmPlanningProblem p = problem(b);
  p.goal = q7(1.2, 0.5, 0, 2.0, 0, 0, 0);  // the forearm in the chest
  ArmPlan plan = plan_arm_motion(p);
  EXPECT_EQ(plan.status, PlanStatus::kGoalInCollision);
  EXPECT_EQ(plan.detail, "self-collision: right_lower_forearm with torso");
  p.start = p.goal;
  EXPECT_EQ(plan_arm_motion(p).status, PlanStatus::kStartInCollision);
  p.start = kNeutral;
  p.goal = kReach;
  p.goal(3) = 3.0;  // e1 stops at 2.618
  EXPECT_EQ(plan_arm_motion(p).status, PlanStatus::kGoalOutsideLimits);
}

TEST(ArmPlanner, AStopRequestEndsTheSearch) {
  Baxter b;
  block_the_straight_motion(b);
  ArmPlanningProblem p = problem(b);
  p.time_limit_s = 60.0;
  StopSource source;
  p.stop = source.token();
  source.request_stop();  // as a Timeout node's deadline would, during the search
  const ArmPlan stopped = plan_arm_motion(p);
  EXPECT_EQ(stopped.status, PlanStatus::kCancelled);
  EXPECT_TRUE(stopped.path.empty());
  EXPECT_LT(stopped.planning_s, 60.0);
}

TEST(ArmPlanner, BadProblemsAreErrors) {
  Baxter b;
  ArmPlanningProblem p = problem(b);
  p.planner = "RRTconect";
  EXPECT_NE(error_of([&] {
              plan_arm_motion(p);
            }).find("unknown planner 'RRTconect' (did you mean 'RRTConnect'?)"),
            std::string::npos);
  p = problem(b);
  p.goal = Eigen::VectorXd::Zero(6);
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("7 finite joint values"), std::string::npos);
  p = problem(b);
  p.world = nullptr;
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("needs an arm and a collision world"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode::planning
