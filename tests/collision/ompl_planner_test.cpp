// The ompl_planner component: from Baxter's home configuration to a grasp over the table,
// the motion ends at the grasp, follows a straight approach for its last 10 cm, and never
// passes through the observed points (checked densely); failures are statuses with reasons.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "antipode/core/parameters.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "arm_planner.hpp"
#include "ompl_planner.hpp"
#include "support/error_of.hpp"

namespace antipode::planning {
namespace {

const std::string kUrdf = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf";
const std::string kRobot = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.yaml";

OmplPlanner planner() {
  OmplPlannerOptions o;
  o.robot_file = kUrdf;
  o.arm_tip = "right_gripper";
  o.points_unchecked = {"right_hand"};
  return OmplPlanner(o);
}

JointState home(const OmplPlanner& p) {
  return {p.arm().joint_names(), {0.08, -1.0, 1.19, 1.94, -0.67, 1.03, 0.5}};
}

Hand top_down(double x, double y, double z) {
  Hand hand;
  hand.X_FrameHand.linear().col(0) = -Eigen::Vector3d::UnitZ();
  hand.X_FrameHand.linear().col(1) = Eigen::Vector3d::UnitY();
  hand.X_FrameHand.linear().col(2) = Eigen::Vector3d::UnitX();
  hand.X_FrameHand.translation() = Eigen::Vector3d(x, y, z);
  return hand;
}

// A sheet of points (a table top) at height z over x in [0.4, 1.1], y in [-0.6, 0.3].
std::shared_ptr<Cloud> table_at(double z) {
  auto cloud = std::make_shared<Cloud>();
  for (double x = 0.4; x <= 1.1; x += 0.01)
    for (double y = -0.6; y <= 0.3; y += 0.01)
      cloud->points_m.emplace_back(float(x), float(y), float(z));
  return cloud;
}

TEST(OmplPlanner, ReachesAGraspFromHomeWithAStraightApproach) {
  const OmplPlanner p = planner();
  PlanningProblem problem;
  problem.grasp = top_down(0.72, -0.15, -0.22);
  problem.start = home(p);
  problem.scene = table_at(-0.295);
  problem.seed = 3;
  const PlanningResult result = p.plan(problem);
  ASSERT_EQ(result.status, PlanningStatus::kSolved)
      << to_string(result.status) << " " << result.detail;
  const Trajectory& t = result.trajectory;
  ASSERT_GE(t.positions_rad.size(), 3u);
  EXPECT_EQ(t.joint_names, p.arm().joint_names());
  EXPECT_EQ(t.positions_rad.front(), problem.start.positions_rad);
  for (std::size_t w = 1; w < t.times_s.size(); ++w) EXPECT_GE(t.times_s[w], t.times_s[w - 1]);
  // The end is the grasp (or the grasp turned half a turn about its approach).
  const Eigen::Isometry3d X_end = p.arm().forward(joint_vector(t.positions_rad.back()));
  EXPECT_LT((X_end.translation() - problem.grasp.position_m()).norm(), 1e-4);
  EXPECT_LT((X_end.linear().col(0) - problem.grasp.approach()).norm(), 1e-4);
  EXPECT_TRUE(result.X_BaseHand.isApprox(X_end, 1e-3));
  // The last 10 cm: the hand moves straight down along its approach.
  for (std::size_t w = t.positions_rad.size() - 10; w < t.positions_rad.size(); ++w) {
    const Eigen::Vector3d at = p.arm().forward(joint_vector(t.positions_rad[w])).translation();
    EXPECT_LT(std::hypot(at.x() - 0.72, at.y() + 0.15), 1e-3) << "waypoint " << w;
  }
  // Never through the table, checked at a quarter of the planning resolution.
  const RobotModel robot = RobotModel::load(kUrdf);
  collision::ArmCollisionWorld world(robot, p.arm());
  world.set_points(
      problem.scene->points_m, 0.01,
      {"right_hand", "right_gripper_base", "right_gripper_l_finger", "right_gripper_r_finger"});
  for (std::size_t w = 0; w + 1 < t.positions_rad.size(); ++w)
    EXPECT_TRUE(segment_is_free(world, joint_vector(t.positions_rad[w]),
                                joint_vector(t.positions_rad[w + 1]), 0.005))
        << "segment " << w;
}

TEST(OmplPlanner, FailuresAreStatusesWithTheirReason) {
  const OmplPlanner p = planner();
  PlanningProblem problem;
  problem.start = home(p);
  problem.grasp = top_down(1.5, -0.15, -0.22);  // beyond the arm
  EXPECT_EQ(p.plan(problem).status, PlanningStatus::kNoIkAtGrasp);
  problem.grasp = top_down(0.72, -0.15, -0.22);
  // A sheet of points 12 cm above the grasp: the wrist (from 8 cm above the palm face up)
  // would pass through it at the grasp.
  problem.scene = table_at(-0.10);
  const PlanningResult in_table = p.plan(problem);
  EXPECT_TRUE(in_table.status == PlanningStatus::kGoalInCollision ||
              in_table.status == PlanningStatus::kNoApproach)
      << to_string(in_table.status);
  problem.scene = nullptr;
  problem.start.positions_rad = {1.2, 0.5, 0, 2.0, 0, 0, 0};  // the forearm in the chest
  const PlanningResult start = p.plan(problem);
  EXPECT_EQ(start.status, PlanningStatus::kStartInCollision);
  EXPECT_NE(start.detail.find("with torso"), std::string::npos) << start.detail;
  problem.start.names.pop_back();
  EXPECT_EQ(p.plan(problem).status, PlanningStatus::kStartInvalid);
  problem.start = home(p);
  StopSource source;
  source.request_stop();
  problem.stop = source.token();
  EXPECT_EQ(p.plan(problem).status, PlanningStatus::kCancelled);
}

TEST(OmplPlanner, AGraspInAnotherFrameIsAnError) {
  const OmplPlanner p = planner();
  PlanningProblem problem;
  problem.start = home(p);
  problem.grasp = top_down(0.72, -0.15, -0.22);
  problem.grasp.frame = "camera";
  EXPECT_NE(testing::error_of([&] {
              p.plan(problem);
            }).find("the grasp is in frame 'camera', the robot's base is 'base'"),
            std::string::npos);
}

TEST(OmplPlanner, BadParametersNameTheirKey) {
  const auto error = [](const std::string& yaml) {
    return testing::error_of(
        [&] { OmplPlanner(Parameters(YAML::Load(yaml), "component 'planner'", "trees/t.yaml")); });
  };
  EXPECT_NE(error("robot: robots/nope.yaml").find("robot: robot file"), std::string::npos);
  const std::string urdf = error("robot: " + kUrdf);
  EXPECT_NE(urdf.find("trees/t.yaml:1:"), std::string::npos) << urdf;
  EXPECT_NE(urdf.find("a URDF, not a robot file"), std::string::npos) << urdf;
  EXPECT_NE(error("robot: " + kRobot + "\ntime_limit_s: 0").find("'time_limit_s' must be positive"),
            std::string::npos);
  EXPECT_NE(error("robot: " + kRobot + "\nplaner: RRT").find("did you mean 'planner'?"),
            std::string::npos);
  EXPECT_EQ(error("robot: " + kRobot + "\nsegment_order: in_order"), "");
  EXPECT_NE(error("robot: " + kRobot + "\nsegment_order: random")
                .find("'segment_order' must be rake or in_order, got 'random'"),
            std::string::npos);
  EXPECT_NE(error("robot: " + kRobot + "\nrange_rad: -1")
                .find("'range_rad' must be finite and not negative"),
            std::string::npos);
  EXPECT_NE(error("robot: " + kRobot + "\nplanner: PRM\nrange_rad: 0.5").find("not PRM"),
            std::string::npos);
  EXPECT_EQ(error("robot: " + kRobot + "\nrange_rad: 0.8"), "");
  EXPECT_NE(error("robot: " + kRobot + "\nlate_range_rad: -0.5")
                .find("'late_range_rad' must be finite and not negative (0: keep range_rad)"),
            std::string::npos);
  EXPECT_NE(error("robot: " + kRobot + "\nlate_after_states: -3")
                .find("'late_after_states' must not be negative"),
            std::string::npos);
  EXPECT_EQ(error("robot: " + kRobot + "\nlate_range_rad: 0\nlate_after_states: 500"), "");
}

}  // namespace
}  // namespace antipode::planning
