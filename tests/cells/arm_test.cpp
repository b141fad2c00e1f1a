// The cell's arm: it reports its home state, follows a trajectory to the grasp and then
// grasps; an arm link touching the scene on the way is its own outcome, naming link and
// body; trajectories it cannot follow are refused with the reason.

#include <gtest/gtest.h>

#include "antipode/core/parameters.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"
#include "bullet_cell.hpp"
#include "top_down_hand.hpp"

namespace antipode::cells {
namespace {

const std::string kUrdf = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf";

// A 5 cm upright cylinder, 10 cm tall, at (0.72, -0.12) on the table; Baxter's arm at home.
BulletCell arm_cell(bool with_arm = true) {
  CellOptions options;
  options.sensor.scale = 0.0;
  if (with_arm)
    options.arm =
        CellArmOptions{kUrdf, "right_gripper", {0.08, -1.0, 1.19, 1.94, -0.67, 1.03, 0.5}};
  return BulletCell(
      parse_scene(Parameters(YAML::Load("placement: isolated\nobjects:\n  - { shape: cylinder, "
                                        "size_m: [0.05, 0.1], position_m: [0.72, -0.12] }\n"),
                             "scene 'test.yaml'", "test.yaml")),
      options);
}

// Joint values that put Baxter's right_gripper frame at `X`, from the home configuration.
std::vector<double> ik(const Eigen::Isometry3d& X, const std::vector<double>& seed) {
  static const RobotModel robot = RobotModel::load(kUrdf);
  static const KinematicChain arm = robot.chain("base", "right_gripper");
  const IkResult result = solve_ik(arm, X, joint_vector(seed));
  EXPECT_FALSE(result.solutions.empty());
  if (result.solutions.empty()) return seed;
  return joint_values(result.solutions.front());
}

// home -> `hand` moved `back_m` back along its approach -> `hand`.
GraspRequest through_pregrasp(const Cell& cell, const Hand& hand, double back_m = 0.10) {
  const JointState home = cell.arm_state();
  Eigen::Isometry3d pre = hand.X_FrameHand;
  pre.translation() -= hand.approach() * back_m;
  const std::vector<double> q_pre = ik(pre, home.positions_rad);
  const std::vector<double> q_grasp = ik(hand.X_FrameHand, q_pre);
  return {hand, HandGeometry{},
          Trajectory{home.names, {home.positions_rad, q_pre, q_grasp}, {0.0, 2.0, 3.0}}};
}

TEST(CellArm, StartsAtHome) {
  const BulletCell cell = arm_cell();
  const JointState state = cell.arm_state();
  ASSERT_EQ(state.names.size(), 7u);
  EXPECT_EQ(state.names.front(), "right_s0");
  EXPECT_EQ(state.positions_rad, (std::vector<double>{0.08, -1.0, 1.19, 1.94, -0.67, 1.03, 0.5}));
  EXPECT_TRUE(arm_cell(false).arm_state().empty());
}

TEST(CellArm, FollowsTheTrajectoryThenGrasps) {
  BulletCell cell = arm_cell();
  const Hand hand = testing::top_down(0.72, -0.12, cell.scene().table.top_z_m + 0.105);
  const GraspAttempt attempt = cell.execute(through_pregrasp(cell, hand));
  EXPECT_EQ(attempt.outcome, GraspOutcome::kSuccess) << attempt.reason;
}

TEST(CellArm, AnArmLinkInTheTableIsACollisionWithTheEnvironment) {
  BulletCell cell = arm_cell();
  // The palm face 7 cm below the table top, beside the cylinder: the flange (4.5 cm above
  // the palm face) is 2.5 cm in the table.
  const Hand hand = testing::top_down(0.60, -0.30, cell.scene().table.top_z_m - 0.07);
  const GraspAttempt attempt = cell.execute(through_pregrasp(cell, hand));
  EXPECT_EQ(attempt.outcome, GraspOutcome::kArmCollision);
  EXPECT_NE(attempt.reason.find("touched table"), std::string::npos) << attempt.reason;
  EXPECT_NE(attempt.reason.find("the arm's right_"), std::string::npos) << attempt.reason;
  EXPECT_EQ(cell.objects().size(), 1u) << "the attempt ends before the gripper moves";
}

TEST(CellArm, TrajectoriesItCannotFollowAreRefusedWithTheReason) {
  BulletCell cell = arm_cell();
  const Hand hand = testing::top_down(0.72, -0.12, cell.scene().table.top_z_m + 0.105);
  GraspRequest request = through_pregrasp(cell, hand);
  GraspRequest away = request;
  away.trajectory.positions_rad.front()[0] += 0.2;
  EXPECT_NE(cell.execute(away).reason.find("starts away from the arm's state (right_s0)"),
            std::string::npos);
  GraspRequest elsewhere = request;
  elsewhere.grasp.X_FrameHand.translation().x() += 0.05;
  const GraspAttempt short_of = cell.execute(elsewhere);
  EXPECT_EQ(short_of.outcome, GraspOutcome::kNotExecuted);
  EXPECT_NE(short_of.reason.find("the trajectory ends 50 mm and 0 deg from the grasp"),
            std::string::npos)
      << short_of.reason;
  GraspRequest beyond = request;
  beyond.trajectory.positions_rad.back()[3] = 3.0;  // e1 stops at 2.618
  EXPECT_NE(cell.execute(beyond).reason.find("waypoint 2: right_e1 is outside its limits"),
            std::string::npos);
  BulletCell no_arm = arm_cell(false);
  EXPECT_NE(no_arm.execute(request).reason.find("the cell has no arm"), std::string::npos);
}

}  // namespace
}  // namespace antipode::cells
