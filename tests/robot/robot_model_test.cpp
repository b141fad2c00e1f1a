// The Baxter model of robots/baxter against the forward-kinematics values of
// shared/reference/baxter.md, and the errors of bad robot descriptions.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_model.hpp"
#include "support/error_of.hpp"

namespace antipode {
namespace {

using testing::error_of;

const std::string kBaxter = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf";

RobotModel baxter() { return RobotModel::load(kBaxter); }

Eigen::VectorXd q7(double s0, double s1, double e0, double e1, double w0, double w1, double w2) {
  Eigen::VectorXd q(7);
  q << s0, s1, e0, e1, w0, w1, w2;
  return q;
}

struct FkCase {
  Eigen::VectorXd q;
  Eigen::Vector3d position;
  Eigen::Quaterniond rotation;  // w, x, y, z
};

// baxter.md, "Forward-kinematics check values (right_hand in base)".
std::vector<FkCase> fk_cases() {
  return {
      {q7(0, 0, 0, 0, 0, 0, 0),
       {0.79746, -0.99246, 0.32098},
       {0.65328, 0.27060, 0.65328, -0.27060}},
      {q7(0, -0.55, 0, 0.75, 0, 1.26, 0),
       {0.63393, -0.82893, 0.21935},
       {0.05116, 0.38210, 0.92246, -0.02119}},
      {q7(0.08, -1, 1.19, 1.94, -0.67, 1.03, 0.5),
       {0.57123, -0.18079, 0.27115},
       {0.02550, -0.14077, 0.98965, -0.01165}},
      {q7(1, -2.07, -3, 2.55, 0, 0.01, 0),
       {-0.12538, -0.35744, 0.08642},
       {0.04058, 0.98442, 0.16704, -0.03695}},
      {q7(0.5, -0.6, 0.3, 1.2, -0.4, 0.9, 0.7),
       {0.79911, -0.35914, 0.11723},
       {0.06807, 0.29094, 0.95409, -0.02081}},
  };
}

TEST(BaxterModel, RightArmChainHasTheSevenJointsAndTheirLimits) {
  const KinematicChain arm = baxter().chain("base", "right_hand");
  ASSERT_EQ(arm.dof(), 7u);
  EXPECT_EQ(arm.joint_names(),
            (std::vector<std::string>{"right_s0", "right_s1", "right_e0", "right_e1", "right_w0",
                                      "right_w1", "right_w2"}));
  EXPECT_DOUBLE_EQ(arm.limits()[1].lower, -2.147);
  EXPECT_DOUBLE_EQ(arm.limits()[1].upper, 1.047);
  EXPECT_DOUBLE_EQ(arm.limits()[3].lower, -0.05);
  EXPECT_DOUBLE_EQ(arm.limits()[6].velocity, 4.0);
}

TEST(BaxterModel, ForwardKinematicsMatchesTheReferenceValues) {
  const KinematicChain arm = baxter().chain("base", "right_hand");
  for (const FkCase& c : fk_cases()) {
    const Eigen::Isometry3d x = arm.forward(c.q);
    EXPECT_LT((x.translation() - c.position).norm(), 1e-4) << c.q.transpose();
    // The reference quaternions are rounded to 5 decimals; q and -q are the same turn.
    EXPECT_GT(std::abs(Eigen::Quaterniond(x.linear()).dot(c.rotation.normalized())), 1 - 1e-8)
        << c.q.transpose();
  }
}

TEST(BaxterModel, IntermediateFramesAtZeroMatchTheReference) {
  const RobotModel robot = baxter();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(7);
  const struct {
    const char* link;
    int joints;
    Eigen::Vector3d position;
  } frames[] = {{"right_upper_shoulder", 1, {0.06403, -0.25903, 0.12963}},
                {"right_lower_shoulder", 2, {0.11282, -0.30782, 0.39998}},
                {"right_lower_elbow", 4, {0.37050, -0.56550, 0.33098}},
                {"right_lower_forearm", 6, {0.63516, -0.83017, 0.32098}},
                {"right_wrist", 7, {0.71717, -0.91217, 0.32098}}};
  for (const auto& f : frames) {
    const KinematicChain chain = robot.chain("base", f.link);
    ASSERT_EQ(chain.dof(), static_cast<std::size_t>(f.joints)) << f.link;
    EXPECT_LT((chain.forward(zero.head(f.joints)).translation() - f.position).norm(), 1e-4)
        << f.link;
  }
}

TEST(BaxterModel, LeftArmMirrorsTheRightArm) {
  const RobotModel robot = baxter();
  const Eigen::VectorXd q = q7(0.5, -0.6, 0.3, 1.2, -0.4, 0.9, 0.7);
  Eigen::VectorXd mirrored = q;  // reflection in the y = 0 plane negates the twisting joints
  for (int i : {0, 2, 4, 6}) mirrored(i) = -q(i);
  const Eigen::Vector3d right = robot.chain("base", "right_hand").forward(q).translation();
  const Eigen::Vector3d left = robot.chain("base", "left_hand").forward(mirrored).translation();
  EXPECT_LT((left - Eigen::Vector3d(right.x(), -right.y(), right.z())).norm(), 1e-9);
}

TEST(BaxterModel, GraspFrameIsThePalmFaceWithTheApproachAlongTheFlangeAxis) {
  const RobotModel robot = baxter();
  const Eigen::VectorXd q = q7(0.5, -0.6, 0.3, 1.2, -0.4, 0.9, 0.7);
  const Eigen::Isometry3d hand = robot.chain("base", "right_hand").forward(q);
  const Eigen::Isometry3d grasp = robot.chain("base", "right_gripper").forward(q);
  const Eigen::Vector3d flange_z = hand.linear().col(2);
  EXPECT_LT((grasp.linear().col(0) - flange_z).norm(), 1e-9);              // approach
  EXPECT_LT((grasp.linear().col(1) - hand.linear().col(1)).norm(), 1e-9);  // closing
  EXPECT_LT((grasp.translation() - (hand.translation() + 0.045 * flange_z)).norm(), 1e-9);
}

TEST(BaxterModel, JacobianMatchesFiniteDifferencesOfForwardKinematics) {
  const KinematicChain arm = baxter().chain("base", "right_hand");
  const Eigen::VectorXd q = q7(0.3, -0.4, 0.5, 1.0, -0.2, 0.8, 0.1);
  const auto j = arm.jacobian(q);
  const double h = 1e-6;
  for (int i = 0; i < 7; ++i) {
    Eigen::VectorXd qh = q;
    qh(i) += h;
    const Eigen::Vector3d dp = (arm.forward(qh).translation() - arm.forward(q).translation()) / h;
    EXPECT_LT((dp - j.col(i).head<3>()).norm(), 1e-5) << "joint " << i;
  }
}

TEST(BaxterModel, LinkPosesInOnePassMatchEachLinksOwnChain) {
  const RobotModel robot = baxter();
  const KinematicChain arm = robot.chain("base", "right_gripper");
  const Eigen::VectorXd q = q7(0.5, -0.6, 0.3, 1.2, -0.4, 0.9, 0.7);
  const std::vector<std::string> names = arm.link_names();
  const std::vector<Eigen::Isometry3d> poses = arm.link_poses(q);
  ASSERT_EQ(names.size(), poses.size());
  EXPECT_EQ(names.front(), "torso");
  EXPECT_EQ(names.back(), "right_gripper");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const KinematicChain part = robot.chain("base", names[i]);
    const Eigen::Isometry3d expected = part.forward(q.head(Eigen::Index(part.dof())));
    EXPECT_TRUE(poses[i].isApprox(expected, 1e-12)) << names[i];
  }
}

TEST(BaxterModel, FingersArePrismaticWithTheStrokeOfTheSetting) {
  const KinematicChain finger = baxter().chain("right_gripper_base", "right_gripper_l_finger");
  ASSERT_EQ(finger.dof(), 1u);
  EXPECT_NEAR(finger.limits()[0].upper - finger.limits()[0].lower, 0.02085, 1e-9);
}

TEST(RobotModelErrors, NameTheFileTheLinkAndTheFix) {
  EXPECT_NE(error_of([] {
              RobotModel::load("/nonexistent/robot.urdf");
            }).find("/nonexistent/robot.urdf: cannot open"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              RobotModel::parse("<robot name='r'><link name='a'/>", "r.urdf");
            }).find("r.urdf: "),
            std::string::npos);
  EXPECT_NE(error_of([] { RobotModel::parse("not xml at all", "bad.urdf"); }).find("bad.urdf"),
            std::string::npos);
  // 100,000 nested elements: refused where they pass 100 levels, not a stack overflow.
  std::string deep = "<robot name='r'><link name='a'/>";
  for (int i = 0; i < 100000; ++i) deep += "<x>";
  for (int i = 0; i < 100000; ++i) deep += "</x>";
  deep += "</robot>";
  EXPECT_NE(error_of([&] { RobotModel::parse(deep, "deep.urdf"); })
                .find("deep.urdf: not XML a robot description can be: elements nested deeper "
                      "than 100 levels, at line 1"),
            std::string::npos);
  const RobotModel robot = baxter();
  EXPECT_NE(error_of([&] {
              robot.chain("base", "right_hnd");
            }).find("no link 'right_hnd' (did you mean 'right_hand'?)"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              robot.chain("right_hand", "base");
            }).find("link 'base' is not below 'right_hand'"),
            std::string::npos);
  const KinematicChain arm = robot.chain("base", "right_hand");
  EXPECT_NE(error_of([&] {
              arm.forward(Eigen::VectorXd::Zero(6));
            }).find("6 joint values for the 7 joints from 'base' to 'right_hand'"),
            std::string::npos);
  EXPECT_NE(
      error_of([&] { arm.forward(Eigen::VectorXd::Constant(7, std::nan(""))); }).find("finite"),
      std::string::npos);
}

TEST(RobotModel, FloatingJointsCannotFormAChain) {
  const RobotModel robot = RobotModel::parse(
      "<robot name='r'><link name='a'/><link name='b'/>"
      "<joint name='j' type='floating'><parent link='a'/><child link='b'/></joint></robot>",
      "floating.urdf");
  EXPECT_NE(error_of([&] { robot.chain("a", "b"); }).find("joint 'j' is floating or planar"),
            std::string::npos);
}

// Limits no position satisfies are refused when the chain is built, naming the joint: a
// planner would otherwise search an empty space and report only that it found nothing.
TEST(RobotModel, InvertedJointLimitsAreRefused) {
  const RobotModel robot = RobotModel::parse(
      "<robot name='r'><link name='a'/><link name='b'/>"
      "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/>"
      "<limit lower='1.0' upper='-1.0' effort='1' velocity='1'/></joint></robot>",
      "inverted.urdf");
  EXPECT_NE(error_of([&] { robot.chain("a", "b"); })
                .find("inverted.urdf: joint 'j' has its lower limit (1.000000) above its upper "
                      "limit (-1.000000)"),
            std::string::npos)
      << error_of([&] { robot.chain("a", "b"); });
}

}  // namespace
}  // namespace antipode
