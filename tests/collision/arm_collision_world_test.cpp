// The collision world of Baxter's right arm: which link pairs it checks, known free and
// self-colliding configurations, boxes and observed points in the way.

#include <string>

#include <gtest/gtest.h>

#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "support/error_of.hpp"

namespace antipode::collision {
namespace {

using testing::error_of;

const RobotModel& baxter() {
  static const RobotModel robot =
      RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf");
  return robot;
}

ArmCollisionWorld right_arm_world() {
  return ArmCollisionWorld(baxter(), baxter().chain("base", "right_gripper"));
}

Eigen::VectorXd q7(double s0, double s1, double e0, double e1, double w0, double w1, double w2) {
  Eigen::VectorXd q(7);
  q << s0, s1, e0, e1, w0, w1, w2;
  return q;
}

// The right gripper's grasp frame at `q`.
Eigen::Vector3d gripper_at(const Eigen::VectorXd& q) {
  return baxter().chain("base", "right_gripper").forward(q).translation();
}

const Eigen::VectorXd kNeutral = q7(0, -0.55, 0, 0.75, 0, 1.26, 0);  // baxter.md
const Eigen::VectorXd kUntucked = q7(0.08, -1, 1.19, 1.94, -0.67, 1.03, 0.5);

TEST(ArmCollisionWorld, TheRobotsWorkingConfigurationsAreFree) {
  const ArmCollisionWorld world = right_arm_world();
  EXPECT_TRUE(world.check(kNeutral).free()) << world.check(kNeutral).str();
  EXPECT_TRUE(world.check(kUntucked).free()) << world.check(kUntucked).str();
}

TEST(ArmCollisionWorld, AnArmFoldedIntoTheBodyCollidesWithIt) {
  const ArmCollisionWorld world = right_arm_world();
  // Shoulder swung in, elbow bent: the forearm passes through the chest.
  const ContactReport forearm = world.check(q7(1.2, 0.5, 0, 2.0, 0, 0, 0));
  EXPECT_EQ(forearm.kind, ContactReport::Kind::kSelf);
  EXPECT_EQ(forearm.str(), "self-collision: right_lower_forearm with torso");
  // Elbow folded fully and the wrist bent back: the gripper meets the shoulder.
  const ContactReport gripper = world.check(q7(0, 1.0, 0, 2.6, 0, 2.0, 0));
  EXPECT_EQ(gripper.kind, ContactReport::Kind::kSelf);
  EXPECT_EQ(gripper.link, "right_gripper_base");
}

TEST(ArmCollisionWorld, ChecksLinksThreeOrMoreJointsApart) {
  const ArmCollisionWorld world = right_arm_world();
  auto checked = [&](const std::string& a, const std::string& b) {
    for (const auto& p : world.self_pairs())
      if ((p.first == a && p.second == b) || (p.first == b && p.second == a)) return true;
    return false;
  };
  EXPECT_TRUE(checked("right_wrist", "torso"));
  EXPECT_TRUE(checked("right_hand", "right_upper_elbow"));  // e1, w0, w1, w2 apart
  EXPECT_TRUE(checked("right_lower_elbow", "left_lower_elbow"));
  EXPECT_FALSE(checked("right_upper_forearm", "right_wrist"));  // w1, w2: two joints
  EXPECT_FALSE(checked("right_hand", "right_gripper_base"));    // rigidly attached
  EXPECT_FALSE(checked("torso", "pedestal"));                   // neither moves with the arm
  EXPECT_EQ(world.arm_links().size(), 11u);  // 7 arm links, hand, gripper base, 2 fingers
}

TEST(ArmCollisionWorld, ABoxAtTheGripperCollidesAndOneAwayDoesNot) {
  ArmCollisionWorld world = right_arm_world();
  Eigen::Isometry3d X_BaseBox = Eigen::Isometry3d::Identity();
  X_BaseBox.translation() = gripper_at(kNeutral) + Eigen::Vector3d(0.5, 0.0, 0.0);
  world.add_box("crate", X_BaseBox, Eigen::Vector3d(0.1, 0.1, 0.1));
  EXPECT_TRUE(world.check(kNeutral).free());
  X_BaseBox.translation() = gripper_at(kNeutral);
  world.add_box("wall", X_BaseBox, Eigen::Vector3d(0.1, 0.1, 0.1));
  const ContactReport r = world.check(kNeutral);
  EXPECT_EQ(r.kind, ContactReport::Kind::kEnvironment);
  EXPECT_EQ(r.other, "wall");
}

TEST(ArmCollisionWorld, ObservedPointsAtTheGripperCollide) {
  ArmCollisionWorld world = right_arm_world();
  const Eigen::Vector3f at = gripper_at(kNeutral).cast<float>();
  std::vector<Eigen::Vector3f> points;
  for (int i = -5; i <= 5; ++i) points.push_back(at + Eigen::Vector3f(0, 0, 0.01f * float(i)));
  world.set_points(points, 0.01);
  EXPECT_EQ(world.check(kNeutral).str().rfind("collision: ", 0), 0u);
  EXPECT_EQ(world.check(kNeutral).other, "points");
  for (auto& p : points) p.x() += 0.5f;  // the same points half a metre away
  world.set_points(points, 0.01);
  EXPECT_TRUE(world.check(kNeutral).free());
  world.set_points({}, 0.01);
  EXPECT_TRUE(world.check(kNeutral).free());
}

TEST(ArmCollisionWorld, BadInputIsAnError) {
  EXPECT_NE(
      error_of([] {
        ArmCollisionWorld(baxter(), baxter().chain("base", "right_gripper"), {{"left_e11", 0.5}});
      }).find("no joint 'left_e11' (did you mean 'left_e1'?)"),
      std::string::npos);
  EXPECT_NE(error_of([] {
              ArmCollisionWorld(baxter(), baxter().chain("torso", "right_gripper"));
            }).find("must start at the robot's root link 'base'"),
            std::string::npos);
  ArmCollisionWorld world = right_arm_world();
  EXPECT_NE(error_of([&] {
              world.set_points({Eigen::Vector3f::Zero()}, 0.0);
            }).find("resolution must be in [0.001, 1] m"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              world.add_box("flat", Eigen::Isometry3d::Identity(), Eigen::Vector3d(1, 1, 0));
            }).find("box 'flat' needs positive sizes"),
            std::string::npos);
  EXPECT_NE(error_of([&] { world.check(Eigen::VectorXd::Zero(3)); }).find("3 joint values"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode::collision
