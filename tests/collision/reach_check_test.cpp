// Reach checks of Baxter's right arm over a box on the table: a grasp from above is
// reachable, one whose approach passes through the box's near wall is rejected with the
// wall named, and the same grasp is reachable once the wall is gone.

#include <algorithm>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_model.hpp"
#include "reach_check.hpp"

namespace antipode::collision {
namespace {

const RobotModel& baxter() {
  static const RobotModel robot =
      RobotModel::load(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.urdf");
  return robot;
}

Eigen::Isometry3d hand_at(const Eigen::Vector3d& position, const Eigen::Vector3d& approach) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d closing = approach.unitOrthogonal();
  X.linear().col(0) = approach.normalized();
  X.linear().col(1) = closing;
  X.linear().col(2) = approach.normalized().cross(closing);
  X.translation() = position;
  return X;
}

Eigen::Isometry3d box_at(double x, double y, double z) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(x, y, z);
  return X;
}

// The table top at z = -0.295 and a box's near wall (the one facing the robot) at x = 0.6.
void add_table_and_near_wall(ArmCollisionWorld& world) {
  world.add_box("table", box_at(0.8, -0.2, -0.32), Eigen::Vector3d(0.8, 1.2, 0.05));
  world.add_box("near_wall", box_at(0.6, -0.2, -0.22), Eigen::Vector3d(0.01, 0.3, 0.15));
}

void expect_at(const KinematicChain& arm, const Eigen::VectorXd& q, const Eigen::Isometry3d& X) {
  EXPECT_LT((arm.forward(q).translation() - X.translation()).norm(), 1e-4);
}

TEST(ReachCheck, AGraspFromAboveIsReachableWithItsPreGrasp) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  ArmCollisionWorld world(baxter(), arm);
  add_table_and_near_wall(world);
  const Eigen::Isometry3d X = hand_at({0.72, -0.2, -0.17}, -Eigen::Vector3d::UnitZ());
  const Reach reach = check_reach(arm, world, X, arm.mid_range());
  ASSERT_EQ(reach.status, ReachStatus::kReachable)
      << to_string(reach.status) << " " << reach.detail;
  expect_at(arm, reach.q_grasp, X);
  Eigen::Isometry3d pre = X;
  pre.translation().z() += 0.10;  // 10 cm back along the downward approach
  expect_at(arm, reach.q_pregrasp, pre);
  EXPECT_TRUE(world.check(reach.q_grasp).free());
  EXPECT_TRUE(world.check(reach.q_pregrasp).free());
}

TEST(ReachCheck, AGraspBehindTheBoxWallIsRejectedWithTheWallNamed) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  // Just inside the near wall, below its top, the approach horizontal through the wall.
  const Eigen::Isometry3d X = hand_at({0.64, -0.2, -0.2}, Eigen::Vector3d::UnitX());
  {
    ArmCollisionWorld open(baxter(), arm);  // the same grasp without the box is reachable
    open.add_box("table", box_at(0.8, -0.2, -0.32), Eigen::Vector3d(0.8, 1.2, 0.05));
    const Reach reach = check_reach(arm, open, X, arm.mid_range());
    ASSERT_EQ(reach.status, ReachStatus::kReachable)
        << to_string(reach.status) << " " << reach.detail;
  }
  ArmCollisionWorld world(baxter(), arm);
  add_table_and_near_wall(world);
  const Reach reach = check_reach(arm, world, X, arm.mid_range());
  EXPECT_TRUE(reach.status == ReachStatus::kInCollisionAtGrasp ||
              reach.status == ReachStatus::kInCollisionAtPreGrasp)
      << to_string(reach.status);
  EXPECT_NE(reach.detail.find("with near_wall"), std::string::npos) << reach.detail;
}

// A hand at `position` approaching along `approach`, closing horizontally, as given or
// turned half a turn about the approach (the same grasp for a parallel gripper).
bool reachable(const KinematicChain& arm, const ArmCollisionWorld& world,
               const Eigen::Vector3d& position, const Eigen::Vector3d& approach) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d a = approach.normalized();
  const Eigen::Vector3d closing = std::abs(a.z()) > 0.9
                                      ? Eigen::Vector3d::UnitY()
                                      : Eigen::Vector3d::UnitZ().cross(a).normalized();
  X.linear().col(0) = a;
  X.linear().col(1) = closing;
  X.linear().col(2) = a.cross(closing);
  X.translation() = position;
  return check_reach(arm, world, X, arm.mid_range()).status == ReachStatus::kReachable ||
         check_reach(arm, world, half_turned(X), arm.mid_range()).status == ReachStatus::kReachable;
}

// Over the isolation region (docs/robot.md): from above the arm reaches the object whichever
// way the fingers close; horizontally only from its own side, not from the far side.
TEST(ReachCheck, OverTheIsolationRegionFromAboveAndFromTheNearSideOnly) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  const ArmCollisionWorld world(baxter(), arm);
  const Eigen::Vector3d object(0.71, -0.13, -0.21);
  for (int yaw_deg = 0; yaw_deg < 180; yaw_deg += 30) {
    const double yaw = yaw_deg * M_PI / 180.0;
    Eigen::Isometry3d X = hand_at(object, -Eigen::Vector3d::UnitZ());
    X.linear() = X.linear() * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitX());
    EXPECT_EQ(check_reach(arm, world, X, arm.mid_range()).status, ReachStatus::kReachable)
        << "from above, closing at " << yaw_deg << " deg";
  }
  EXPECT_TRUE(reachable(arm, world, object, Eigen::Vector3d::UnitX()));    // away from the robot
  EXPECT_FALSE(reachable(arm, world, object, -Eigen::Vector3d::UnitX()));  // towards it
  EXPECT_FALSE(reachable(arm, world, object, Eigen::Vector3d::UnitY()));   // from its right
}

// The search written out plainly, as the reference: every IK solution at the grasp; for each
// free one in turn, every pre-grasp solution from it, nearest first; the first free pair.
// Without one, a hand in contact at the grasp or the pre-grasp says why before IK does.
Reach reference_reach(const KinematicChain& arm, const ArmCollisionWorld& world,
                      const Eigen::Isometry3d& X) {
  IkOptions ik;
  ik.max_solutions = 12;
  const IkResult grasp = solve_ik(arm, X, arm.mid_range(), ik);
  Reach reach;
  Eigen::Isometry3d pre_pose = X;
  pre_pose.translation() -= 0.10 * X.linear().col(0);
  ik.iterations_per_descent = 100;
  if (!grasp.solutions.empty()) reach.status = ReachStatus::kInCollisionAtGrasp;
  for (const Eigen::VectorXd& q : grasp.solutions) {
    if (!world.check(q).free()) continue;
    IkResult pre = solve_ik(arm, pre_pose, q, ik);
    if (pre.solutions.empty() && reach.status == ReachStatus::kInCollisionAtGrasp)
      reach.status = ReachStatus::kNoIkAtPreGrasp;
    std::sort(pre.solutions.begin(), pre.solutions.end(),
              [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
                return (a - q).squaredNorm() < (b - q).squaredNorm();
              });
    for (const Eigen::VectorXd& p : pre.solutions) {
      if (world.check(p).free()) return {ReachStatus::kReachable, q, p, ""};
      reach.status = ReachStatus::kInCollisionAtPreGrasp;
    }
  }
  // The hand in contact at the grasp, or at the pre-grasp, is the reason first.
  if (const ContactReport c = world.check_tip_links(X); !c.free())
    return {ReachStatus::kInCollisionAtGrasp, {}, {}, c.str()};
  if (const ContactReport c = world.check_tip_links(pre_pose); !c.free())
    return {ReachStatus::kInCollisionAtPreGrasp, {}, {}, c.str()};
  return reach;
}

bool same_values(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.size() == 0 || a == b);
}

// Over a grid of grasps over the box, near its wall and beyond the arm's reach, every search
// gives the reference's status; nearest_pregrasp and exhaustive its joint values, and
// first_free its grasp solution with a free pre-grasp at the stand-off.
TEST(ReachCheck, EverySearchGivesTheReferenceAnswer) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  ArmCollisionWorld world(baxter(), arm);
  add_table_and_near_wall(world);
  std::map<ReachStatus, int> statuses;
  for (double x = 0.5; x <= 1.1; x += 0.1) {
    for (double z = -0.25; z <= -0.05; z += 0.1) {
      for (const Eigen::Vector3d& approach :
           {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, -1)}) {
        const Eigen::Isometry3d X = hand_at({x, -0.2, z}, approach);
        const Reach reference = reference_reach(arm, world, X);
        const std::string at = "at x " + std::to_string(x) + ", z " + std::to_string(z);
        for (ReachSearch search :
             {ReachSearch::kExhaustive, ReachSearch::kNearestPreGrasp, ReachSearch::kFirstFree}) {
          ReachOptions options;
          options.search = search;
          const Reach r = check_reach(arm, world, X, arm.mid_range(), options);
          ASSERT_EQ(r.status, reference.status) << at << ", " << to_string(search);
          EXPECT_TRUE(same_values(r.q_grasp, reference.q_grasp)) << at << ", " << to_string(search);
          if (search != ReachSearch::kFirstFree) {
            EXPECT_TRUE(same_values(r.q_pregrasp, reference.q_pregrasp)) << at;
          } else if (r.status == ReachStatus::kReachable) {
            EXPECT_TRUE(world.check(r.q_pregrasp).free()) << at;
            Eigen::Isometry3d pre = X;
            pre.translation() -= 0.10 * X.linear().col(0);
            expect_at(arm, r.q_pregrasp, pre);
          }
        }
        ++statuses[reference.status];
      }
    }
  }
  // The grid holds reachable grasps, grasps beyond the arm and grasps whose arm meets the wall
  // or the table.
  EXPECT_GE(statuses[ReachStatus::kReachable], 5);
  EXPECT_GT(statuses[ReachStatus::kNoIkAtGrasp], 0);
  EXPECT_GT(
      statuses[ReachStatus::kInCollisionAtGrasp] + statuses[ReachStatus::kInCollisionAtPreGrasp],
      0);
}

TEST(ReachCheck, SearchNamesReadAndAnUnknownOneIsRefused) {
  for (ReachSearch s :
       {ReachSearch::kFirstFree, ReachSearch::kNearestPreGrasp, ReachSearch::kExhaustive})
    EXPECT_EQ(reach_search(to_string(s)), s);
  try {
    reach_search("first_fre");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'first_free'"), std::string::npos)
        << e.what();
  }
}

// The hand alone decides before any IK: a grasp beyond the arm whose hand is inside a crate
// is in collision at the grasp, with the crate named, in every search; a grasp the arm takes
// whose hand meets a crate only at the pre-grasp is in collision at the pre-grasp.
TEST(ReachCheck, AHandInContactIsInCollisionWhateverIkWouldFind) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  const Eigen::Isometry3d beyond = hand_at({2.0, -0.2, 0.0}, Eigen::Vector3d::UnitX());
  const Eigen::Isometry3d above = hand_at({0.72, -0.2, -0.17}, -Eigen::Vector3d::UnitZ());
  ReachOptions options;
  options.pregrasp_m = 0.5;
  Eigen::Isometry3d pregrasp = above;
  pregrasp.translation().z() += options.pregrasp_m;
  ArmCollisionWorld world(baxter(), arm);
  world.add_box("crate", beyond, Eigen::Vector3d(0.3, 0.3, 0.3));
  ASSERT_EQ(check_reach(arm, world, above, arm.mid_range(), options).status,
            ReachStatus::kReachable);
  // 5 cm up the hand from its grasp frame: inside the housing at the pre-grasp only.
  world.add_box("crate", box_at(0.72, -0.2, pregrasp.translation().z() + 0.05),
                Eigen::Vector3d(0.04, 0.04, 0.04));
  ASSERT_TRUE(world.check_tip_links(above).free());
  ASSERT_FALSE(world.check_tip_links(pregrasp).free());
  for (ReachSearch search :
       {ReachSearch::kExhaustive, ReachSearch::kNearestPreGrasp, ReachSearch::kFirstFree}) {
    options.search = search;
    const Reach far = check_reach(arm, world, beyond, arm.mid_range(), options);
    EXPECT_EQ(far.status, ReachStatus::kInCollisionAtGrasp) << to_string(search);
    EXPECT_NE(far.detail.find("with crate"), std::string::npos) << far.detail;
    const Reach blocked = check_reach(arm, world, above, arm.mid_range(), options);
    EXPECT_EQ(blocked.status, ReachStatus::kInCollisionAtPreGrasp) << to_string(search);
    EXPECT_NE(blocked.detail.find("with crate"), std::string::npos) << blocked.detail;
    EXPECT_EQ(blocked.q_grasp.size(), 0) << to_string(search);
  }
}

// Bad input throws in every search, the hand's check notwithstanding.
TEST(ReachCheck, EverySearchRefusesWhatIkRefuses) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  const Eigen::Isometry3d beyond = hand_at({2.0, -0.2, 0.0}, Eigen::Vector3d::UnitX());
  ArmCollisionWorld world(baxter(), arm);
  world.add_box("crate", beyond, Eigen::Vector3d(0.3, 0.3, 0.3));
  Eigen::Isometry3d sheared = beyond;
  sheared.linear()(0, 1) = 0.5;
  for (ReachSearch search :
       {ReachSearch::kExhaustive, ReachSearch::kNearestPreGrasp, ReachSearch::kFirstFree}) {
    ReachOptions options;
    options.search = search;
    EXPECT_THROW(check_reach(arm, world, beyond, Eigen::VectorXd::Zero(3), options), Error);
    EXPECT_THROW(check_reach(arm, world, sheared, arm.mid_range(), options), Error);
    options.ik.max_solutions = 0;
    EXPECT_THROW(check_reach(arm, world, beyond, arm.mid_range(), options), Error);
  }
}

TEST(ReachCheck, AGraspBeyondTheArmHasNoIk) {
  const KinematicChain arm = baxter().chain("base", "right_gripper");
  const ArmCollisionWorld world(baxter(), arm);
  const Reach reach =
      check_reach(arm, world, hand_at({2.0, -0.2, 0.0}, Eigen::Vector3d::UnitX()), arm.mid_range());
  EXPECT_EQ(reach.status, ReachStatus::kNoIkAtGrasp);
  EXPECT_STREQ(to_string(reach.status), "no IK at the grasp");
}

}  // namespace
}  // namespace antipode::collision
