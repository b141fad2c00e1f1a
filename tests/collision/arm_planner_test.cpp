// OMPL arm planning for Baxter's right arm: paths that avoid a box blocking the straight
// motion (checked densely along the path), the search's range, invalid starts and goals, errors.

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "arm_planner.hpp"
#include "collision_options.hpp"
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

// Whether a segment is free does not depend on the order of its states, so checking them as a
// rake or in order gives the same answers, the same search and the same path, with fewer states
// checked as a rake.
TEST(ArmPlanner, ARakeAndInOrderGiveTheSamePath) {
  Baxter b;
  block_the_straight_motion(b);
  for (std::uint64_t seed : {3, 7, 11}) {
    ArmPlanningProblem p = problem(b, seed);
    const ArmPlan rake = plan_arm_motion(p);
    p.rake_segments = false;
    const ArmPlan in_order = plan_arm_motion(p);
    ASSERT_EQ(rake.status, PlanStatus::kSolved);
    ASSERT_EQ(in_order.status, PlanStatus::kSolved);
    ASSERT_EQ(rake.path.size(), in_order.path.size()) << "seed " << seed;
    for (std::size_t i = 0; i < rake.path.size(); ++i) EXPECT_EQ(rake.path[i], in_order.path[i]);
    // The same motions checked, but the blocked ones stop sooner: the count of states checked
    // (each motion's up to its first contact) tells that the rake was used.
    EXPECT_LT(rake.collision_checks, in_order.collision_checks) << "seed " << seed;
  }
  EXPECT_FALSE(segment_is_free(b.world, kNeutral, kReach, 0.005, false));
  EXPECT_FALSE(segment_is_free(b.world, kNeutral, kReach, 0.005, true));
}

// The same answer for every motion, checked as a rake or in order, in each check mode, with
// boxes and points in the arm's way: 300 random motions, half of them blocked somewhere.
TEST(ArmPlanner, ARakeAndInOrderCallTheSameMotionsFree) {
  const RobotModel robot =
      RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf");
  const KinematicChain arm = robot.chain("base", "right_gripper");
  std::vector<Eigen::Vector3f> points;
  points.reserve(3000);
  RandomStream scatter(5);
  for (int i = 0; i < 3000; ++i)  // a slab of points in front of the robot
    points.emplace_back(float(scatter.uniform(0.5, 0.9)), float(scatter.uniform(-0.6, 0.2)),
                        float(scatter.uniform(-0.1, 0.0)));
  for (const collision::CheckMode mode :
       {collision::CheckMode::kExact, collision::CheckMode::kSpheresThenExact,
        collision::CheckMode::kSpheres}) {
    collision::CollisionOptions options;
    options.mode = mode;
    ArmCollisionWorld world(robot, arm, {}, options);
    world.add_box("obstacle", Eigen::Isometry3d(Eigen::Translation3d(0.7, -0.5, 0.3)),
                  Eigen::Vector3d(0.2, 0.2, 0.2));
    world.set_points(points, 0.01, {});
    RandomStream random(9);
    int free = 0;
    for (int i = 0; i < 300; ++i) {
      const Eigen::VectorXd a = arm.random_configuration(random);
      const Eigen::VectorXd b = arm.random_configuration(random);
      const bool rake = segment_is_free(world, a, b, 0.05, true);
      ASSERT_EQ(rake, segment_is_free(world, a, b, 0.05, false))
          << collision::to_string(mode) << ", motion " << i;
      free += rake ? 1 : 0;
    }
    EXPECT_GT(free, 10) << collision::to_string(mode);
    EXPECT_LT(free, 290) << collision::to_string(mode);
  }
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
  p = problem(b);
  p.range_rad = -0.1;
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("range_rad must be finite and not negative"),
            std::string::npos);
  p.range_rad = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("range_rad must be finite"),
            std::string::npos);
  p = problem(b);
  p.planner = "PRM";
  p.range_rad = 0.5;
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("not PRM"), std::string::npos);
  p = problem(b);
  p.late_range_rad = std::nan("");
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("late_range_rad must be finite"),
            std::string::npos);
  p = problem(b);
  p.late_after_states = -1;
  EXPECT_NE(error_of([&] { plan_arm_motion(p); }).find("late_after_states must not be negative"),
            std::string::npos);
}

// A solved, unshortened path from kNeutral to kReach, free, that steps in motions of at most
// `longest_rad`: at least as many as the straight distance (1.15 rad) needs.
void expect_free_path_in_motions_of(const Baxter& b, const ArmPlan& plan, double longest_rad,
                                    double resolution_rad) {
  ASSERT_EQ(plan.status, PlanStatus::kSolved) << to_string(plan.status);
  const double distance = (kReach - kNeutral).norm();
  EXPECT_GE(plan.path.size(), std::size_t(std::ceil(distance / longest_rad)) + 1);
  for (std::size_t i = 0; i + 1 < plan.path.size(); ++i)
    EXPECT_LE((plan.path[i + 1] - plan.path[i]).norm(), longest_rad + 1e-9) << "motion " << i;
  expect_free_path(b, plan, resolution_rad);
}

// The search adds motions no longer than range_rad: in free space, RRTConnect's unshortened
// path steps from the start to the goal in motions of at most that length.
TEST(ArmPlanner, TheRangeBoundsEachMotionOfTheSearch) {
  Baxter b;
  ArmPlanningProblem p = problem(b);
  p.shorten = false;
  p.range_rad = 0.3;
  expect_free_path_in_motions_of(b, plan_arm_motion(p), p.range_rad, p.resolution_rad);
}

// Once the search has checked late_after_states states, its motions are at most
// late_range_rad long: with no budget at all, the whole free-space path steps in them.
TEST(ArmPlanner, ALongSearchGoesOnWithTheLateRange) {
  Baxter b;
  ArmPlanningProblem p = problem(b);
  p.shorten = false;
  p.late_after_states = 0;
  p.late_range_rad = 0.3;
  expect_free_path_in_motions_of(b, plan_arm_motion(p), p.late_range_rad, p.resolution_rad);
}

// A search that ends within the budget is the search without a late range, path for path.
TEST(ArmPlanner, AShortSearchIsNotChangedByTheLateRange) {
  Baxter b;
  block_the_straight_motion(b);
  ArmPlanningProblem p = problem(b);
  p.shorten = false;
  const ArmPlan with_late = plan_arm_motion(p);
  ASSERT_EQ(with_late.status, PlanStatus::kSolved) << to_string(with_late.status);
  ASSERT_LT(with_late.collision_checks, p.late_after_states);
  p.late_range_rad = 0.0;
  const ArmPlan without = plan_arm_motion(p);
  ASSERT_EQ(without.path.size(), with_late.path.size());
  for (std::size_t i = 0; i < without.path.size(); ++i)
    EXPECT_EQ(without.path[i], with_late.path[i]) << "state " << i;
}

}  // namespace
}  // namespace antipode::planning
