// The collision world of Baxter's right arm: which link pairs it checks, known free and
// self-colliding configurations, boxes and observed points in the way.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "collision_pairs.hpp"
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

// The links rigid with the tip are those below the arm's last joint (Baxter's w2).
TEST(ArmCollisionWorld, TheTipLinksAreTheLinksBelowTheLastArmJoint) {
  EXPECT_EQ(right_arm_world().tip_links(),
            (std::vector<std::string>{"right_gripper_base", "right_gripper_l_finger",
                                      "right_gripper_r_finger", "right_hand", "right_wrist"}));
}

// check_tip_links(X) against check(q) at random q with its tip at X, in a world of a table
// and a block of points in front of the robot: whenever the hand alone meets the scene, so
// does the arm (the pre-IK rule is sound); whenever check(q)'s first contact is a tip link's
// with the scene, check_tip_links reports the same contact.
struct Agreement {
  int hand_contacts = 0;  // configurations whose hand alone meets the scene
  int first_at_hand = 0;  // configurations whose first contact is a tip link's with the scene
};

void expect_tip_links_agree(const RobotModel& robot, const std::string& tip,
                            const std::vector<std::string>& unchecked, CheckMode mode,
                            Agreement* seen) {
  const KinematicChain arm = robot.chain(robot.root_link(), tip);
  CollisionOptions options;
  options.mode = mode;
  ArmCollisionWorld world(robot, arm, {}, options);
  Eigen::Isometry3d X_BaseTable = Eigen::Isometry3d::Identity();
  X_BaseTable.translation() = Eigen::Vector3d(0.6, 0.0, -0.35);
  world.add_box("table", X_BaseTable, Eigen::Vector3d(0.8, 1.2, 0.05));
  std::vector<Eigen::Vector3f> points;
  for (float x = 0.35f; x <= 0.75f; x += 0.02f)
    for (float y = -0.3f; y <= 0.3f; y += 0.02f)
      for (float z = -0.3f; z <= 0.0f; z += 0.1f) points.emplace_back(x, y, z);
  world.set_points(points, 0.01, unchecked);
  RandomStream random(7);
  for (int i = 0; i < 3000; ++i) {
    const Eigen::VectorXd q = arm.random_configuration(random);
    const ContactReport hand = world.check_tip_links(arm.forward(q));
    const ContactReport whole = world.check(q);
    if (!hand.free()) {
      ++seen->hand_contacts;
      EXPECT_FALSE(whole.free()) << robot.name() << " " << hand.str();
    }
    const auto& tips = world.tip_links();
    if (whole.kind == ContactReport::Kind::kEnvironment &&
        std::find(tips.begin(), tips.end(), whole.link) != tips.end()) {
      ++seen->first_at_hand;
      if (mode != CheckMode::kSpheres) {
        EXPECT_EQ(hand.str(), whole.str()) << robot.name();
      }
    }
  }
}

TEST(ArmCollisionWorld, TheHandAloneFindsTheArmsContactsOfItsLinks) {
  struct Robot {
    const char* urdf;
    const char* tip;
    std::vector<std::string> unchecked;  // as the robot files leave them against the points
  };
  for (const Robot& r :
       {Robot{"baxter/baxter.urdf", "right_gripper", {"right_hand"}},
        Robot{"panda/panda.urdf", "panda_grasp", {"panda_leftfinger", "panda_rightfinger"}},
        Robot{"ur5e/ur5e.urdf", "ur5e_grasp", {"ur5e_leftfinger", "ur5e_rightfinger"}}}) {
    const RobotModel robot =
        RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/" + r.urdf);
    // Every link checked against the points, and the robot file's links left out, as the
    // selector's world does; in every check mode.
    for (const auto& unchecked :
         {std::vector<std::string>{}, shaped_links_below(robot, r.unchecked)}) {
      for (CheckMode mode :
           {CheckMode::kExact, CheckMode::kSpheresThenExact, CheckMode::kSpheres}) {
        Agreement seen;
        expect_tip_links_agree(robot, r.tip, unchecked, mode, &seen);
        EXPECT_GE(seen.hand_contacts, 100) << r.urdf << ": too few hand contacts to test";
        EXPECT_GE(seen.first_at_hand, 25) << r.urdf << ": too few first contacts at the hand";
      }
    }
  }
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
  Eigen::Isometry3d nan = Eigen::Isometry3d::Identity();
  nan.translation().x() = std::nan("");
  EXPECT_NE(error_of([&] { world.check_tip_links(nan); }).find("tip pose must be finite"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode::collision
