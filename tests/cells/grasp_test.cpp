#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "antipode/core/parameters.hpp"
#include "bullet_cell.hpp"
#include "gripper.hpp"
#include "top_down_hand.hpp"

namespace antipode::cells {
namespace {

SceneSpec parse(const std::string& yaml) {
  return parse_scene(Parameters(YAML::Load(yaml), "scene 'test.yaml'", "test.yaml"));
}

// One upright cylinder of `diameter` and 10 cm height at (0.72, -0.12) on the table.
BulletCell cylinder_cell(double diameter) {
  CellOptions options;
  options.sensor.scale = 0.0;
  return BulletCell(parse("placement: isolated\nobjects:\n  - { shape: cylinder, size_m: [" +
                          std::to_string(diameter) + ", 0.1], position_m: [0.72, -0.12] }\n"),
                    options);
}

using testing::top_down;

// Executes `hand` with Baxter's gripper, free-floating.
GraspAttempt execute(Cell& cell, const Hand& hand) {
  return cell.execute(GraspRequest{hand, HandGeometry{}, {}});
}

double top_of_cylinder(const BulletCell& cell) { return cell.scene().table.top_z_m + 0.1; }

// The cell's ground truth of what is left: each object's name, pose and narrowest horizontal
// extent; a picked object leaves it.
TEST(Grasp, TheObjectTruthNamesWhatIsLeftAndHowWideItLies) {
  CellOptions options;
  options.sensor.scale = 0.0;
  const BulletCell box(parse("placement: isolated\nobjects:\n  - { shape: box, size_m: [0.09, "
                             "0.17, 0.05], position_m: [0.72, -0.12] }\n"),
                       options);
  std::vector<ObjectTruth> truth = box.object_truth();
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_EQ(truth[0].name, "box");
  EXPECT_NEAR(truth[0].narrowest_horizontal_m, 0.09, 1e-3) << "lying flat: too wide to hold";
  EXPECT_NEAR(truth[0].X_BaseObject.translation().x(), 0.72, 0.002);

  BulletCell cell = cylinder_cell(0.05);
  truth = cell.object_truth();
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_EQ(truth[0].name, "cylinder");
  EXPECT_NEAR(truth[0].narrowest_horizontal_m, 0.05, 0.002) << "its faceted mesh";
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  ASSERT_EQ(execute(cell, hand).outcome, GraspOutcome::kSuccess);
  EXPECT_TRUE(cell.object_truth().empty()) << "a picked object leaves the cell";
}

TEST(Grasp, HandAroundA5cmCylinderLiftsIt) {
  BulletCell cell = cylinder_cell(0.05);
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  EXPECT_EQ(execute(cell, hand).outcome, GraspOutcome::kSuccess);
  EXPECT_TRUE(cell.objects().empty()) << "a grasped object is removed";
}

TEST(Grasp, TheRecordTellsWhatHappened) {
  BulletCell cell = cylinder_cell(0.05);
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  const GraspAttempt r = execute(cell, hand);
  ASSERT_EQ(r.outcome, GraspOutcome::kSuccess) << r.reason;
  EXPECT_TRUE(r.reached_pose);
  EXPECT_LT(r.pose_error_m, 0.003);
  EXPECT_TRUE(r.stopped_by.empty());
  EXPECT_TRUE(r.in_collision_at_planned_pose.empty());
  EXPECT_EQ(r.between_fingers_at_detection, std::vector<std::string>{"cylinder"});
  EXPECT_EQ(r.between_fingers_at_closing, std::vector<std::string>{"cylinder"});
  EXPECT_EQ(r.pinched_object, "cylinder");
  EXPECT_NEAR(r.opening_at_contact_m, 0.05, 0.004) << "the fingers stop on the 5 cm cylinder";
  EXPECT_GT(r.lift_m, 0.15);
  EXPECT_TRUE(r.X_BaseHand_planned.isApprox(hand.X_FrameHand));
  EXPECT_GT(r.duration_s, 1.0);
  EXPECT_NE(r.reason.find("held cylinder"), std::string::npos) << r.reason;
  // The true surfaces when the fingers stopped: the cylinder's side between them (2.5 cm from
  // its axis, above the table), every point within 8 cm of the closing region's middle.
  const HandGeometry geometry;
  const Eigen::Vector3d middle =
      r.X_BaseHand_closing * Eigen::Vector3d(geometry.depth_m / 2, 0.0, 0.0);
  int on_the_side = 0;
  for (const Eigen::Vector3f& point : r.surface_at_closing_m) {
    const Eigen::Vector3d p = point.cast<double>();
    EXPECT_LE((r.X_BaseHand_closing.linear().transpose() * (p - middle)).cwiseAbs().maxCoeff(),
              0.08 + 1e-6);
    const double from_axis_m = std::hypot(p.x() - 0.72, p.y() + 0.12);
    if (std::abs(from_axis_m - 0.025) < 0.001 && p.z() > cell.scene().table.top_z_m + 0.001)
      ++on_the_side;
  }
  EXPECT_GT(on_the_side, 100);
}

TEST(Grasp, HandBesideTheCylinderClosesOnNothing) {
  BulletCell cell = cylinder_cell(0.05);
  const Hand hand = top_down(0.72, -0.22, top_of_cylinder(cell) + 0.005);
  const GraspAttempt r = execute(cell, hand);
  EXPECT_EQ(r.outcome, GraspOutcome::kEmptyGrasp);
  EXPECT_TRUE(r.reached_pose);
  EXPECT_TRUE(r.between_fingers_at_detection.empty());
  EXPECT_NE(r.reason.find("no object was between the planned fingers"), std::string::npos)
      << r.reason;
  EXPECT_NEAR(r.opening_at_contact_m, HandGeometry{}.min_aperture_m, 0.001);
  EXPECT_EQ(cell.objects().size(), 1u);
}

// A cylinder against the box's +x wall, the hand straddling both: one finger presses the
// cylinder, the other the wall, the geared fingers stop there and nothing is pinched. The
// record names what each finger presses.
TEST(Grasp, FingersPressingAnObjectAgainstAWallAreNamed) {
  CellOptions options;
  options.sensor.scale = 0.0;
  BulletCell cell(
      parse("placement: isolated\n"
            "box: { center_m: [0.72, -0.12], inner_size_m: [0.30, 0.30], "
            "wall_height_m: 0.06 }\n"
            "objects:\n"
            "  - { shape: cylinder, size_m: [0.04, 0.05], position_m: [0.849, -0.12] }\n"),
      options);
  // The cylinder spans x 0.829-0.869, the wall 0.87-0.88: the hand centred on both.
  const Hand hand = top_down(0.855, -0.12, cell.scene().table.top_z_m + 0.065);
  const GraspAttempt r = execute(cell, hand);
  EXPECT_EQ(r.outcome, GraspOutcome::kEmptyGrasp) << r.reason;
  const auto names = [&](const std::string& part) {
    return std::find(r.touching_at_closing.begin(), r.touching_at_closing.end(), part) !=
           r.touching_at_closing.end();
  };
  EXPECT_TRUE(names("finger -y: cylinder")) << r.reason;
  EXPECT_TRUE(names("finger +y: box wall")) << r.reason;
}

TEST(Grasp, AHandPlannedIntoTheObjectStopsShortAndSaysOnWhat) {
  BulletCell cell = cylinder_cell(0.05);
  // The palm face 3 cm below the cylinder's top: the palm meets the top and stalls (the
  // table holds the cylinder).
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) - 0.03);
  const GraspAttempt r = execute(cell, hand);
  EXPECT_FALSE(r.reached_pose);
  EXPECT_GT(r.pose_error_m, 0.02);
  EXPECT_NE(std::find(r.stopped_by.begin(), r.stopped_by.end(), "palm: cylinder"),
            r.stopped_by.end());
  EXPECT_NE(std::find(r.in_collision_at_planned_pose.begin(), r.in_collision_at_planned_pose.end(),
                      "palm: cylinder"),
            r.in_collision_at_planned_pose.end());
  EXPECT_EQ(r.first_contact, "palm: cylinder");
  EXPECT_NE(r.reason.find("short of the pose"), std::string::npos) << r.reason;
}

// A physics world with the table and one object (an entry of a scene's `objects`), settled.
struct OneObject {
  explicit OneObject(const std::string& entry)
      : spec(parse("placement: isolated\nobjects:\n  - " + entry + "\n")),
        id(build_scene(spec, 0, meshes, world).at(0)) {}
  SceneSpec spec;
  PhysicsWorld world{PhysicsOptions{}};
  MeshCache meshes;
  int id;
};

TEST(Grasp, TheFingersCloseAlikeOnAnObjectOffCentre) {
  // A 4 cm box 1 cm off the hand's centre line: the geared fingers stay symmetric, so the
  // first finger to touch pushes the box to the centre.
  OneObject box("{ shape: box, size_m: [0.04, 0.06, 0.08], position_m: [0.73, -0.12] }");
  GripperOptions options;
  const double top = box.spec.table.top_z_m + 0.08;
  Gripper gripper(box.world, options, top_down(0.72, -0.12, top + 0.002).X_FrameHand);
  box.world.step(24);
  gripper.drive_fingers(-options.finger_speed_m_s);
  box.world.step(120);
  EXPECT_NEAR(gripper.finger_travel_m(0), gripper.finger_travel_m(1), 0.001);
  EXPECT_NEAR(gripper.aperture_m(), 0.04, 0.003);
  EXPECT_NEAR(box.world.pose(box.id).translation().x(), 0.72, 0.003) << "pushed to the centre";
  EXPECT_EQ(gripper.pinched(0.002).size(), 1u);
}

// How fast a 5 cm ball on the table, pinched at its equator, spins about the closing axis
// under a twist of 0.05 N m, for the gripper's torsional friction: a rigid finger meets the
// ball at a point, which resists a twist only through the object's own small spinning friction.
double spin_under_a_twist_rad_s(double torsional_friction_m) {
  OneObject scene("{ shape: sphere, size_m: [0.05], position_m: [0.72, -0.12] }");
  btRigidBody& ball = scene.world.body(scene.id);
  const Eigen::Vector3d centre = scene.world.pose(scene.id).translation();
  GripperOptions options;
  options.torsional_friction_m = torsional_friction_m;
  // The fingertips 15 mm below the equator, 10 mm above the table.
  Gripper gripper(scene.world, options,
                  top_down(centre.x(), centre.y(), centre.z() + 0.045).X_FrameHand);
  gripper.drive_fingers(-options.finger_speed_m_s);
  scene.world.step(120);
  EXPECT_EQ(gripper.pinched(0.002).size(), 1u);
  scene.world.set_before_step([&] { ball.applyTorque(btVector3(0.05f, 0, 0)); });
  scene.world.step(60);
  return std::abs(ball.getAngularVelocity().x());
}

TEST(Grasp, TorsionalFrictionOfThePadsResistsATwist) {
  const double rigid = spin_under_a_twist_rad_s(0.0);
  EXPECT_GT(rigid, 100.0) << "rigid fingers: the ball spins up between them";
  EXPECT_LT(spin_under_a_twist_rad_s(0.005), rigid / 10.0) << "pads with a contact patch";
}

TEST(Grasp, CylinderTooWideForTheGripperIsNotLifted) {
  BulletCell cell = cylinder_cell(0.09);
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  const GraspOutcome outcome = execute(cell, hand).outcome;
  EXPECT_NE(outcome, GraspOutcome::kSuccess) << to_string(outcome);
  EXPECT_EQ(cell.objects().size(), 1u);
}

TEST(Grasp, StartingInCollisionIsACollisionFailure) {
  BulletCell cell = cylinder_cell(0.05);
  // The stand-off pose, 10 cm back along the approach, has the palm inside the cylinder.
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) - 0.05 - 0.1);
  EXPECT_EQ(execute(cell, hand).outcome, GraspOutcome::kCollisionOnApproach);
}

TEST(Grasp, HandsInAnotherFrameOrMalformedAreNotExecuted) {
  BulletCell cell = cylinder_cell(0.05);
  Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  hand.frame = "camera";
  EXPECT_EQ(execute(cell, hand).outcome, GraspOutcome::kNotExecuted);
  hand.frame = "base";
  hand.X_FrameHand.linear() *= 2.0;
  EXPECT_EQ(execute(cell, hand).outcome, GraspOutcome::kNotExecuted);
  EXPECT_EQ(cell.attempts(), 0);
}

// Top-down grasps at every object of a pile, in id order; outcomes and the remaining poses.
std::pair<std::vector<GraspOutcome>, std::vector<Eigen::Matrix4d>> clear_pile(std::uint64_t seed) {
  CellOptions options;
  options.seed = seed;
  BulletCell cell(parse(R"(
box: { inner_size_m: [0.3, 0.3] }
placement: pile
random_objects: { count: 4, shapes: [box, cylinder, sphere, capsule] }
)"),
                  options);
  std::vector<GraspOutcome> outcomes;
  for (int id : cell.objects()) {
    if (!cell.world().has(id)) continue;
    const Eigen::Vector3d p = cell.world().pose(id).translation();
    outcomes.push_back(execute(cell, top_down(p.x(), p.y(), p.z() + 0.02)).outcome);
  }
  std::vector<Eigen::Matrix4d> poses;
  for (int id : cell.objects()) poses.push_back(cell.world().pose(id).matrix());
  return {outcomes, poses};
}

TEST(Grasp, SameSeedSameOutcomes) {
  const auto a = clear_pile(4), b = clear_pile(4);
  EXPECT_EQ(a.first, b.first);
  ASSERT_EQ(a.second.size(), b.second.size());
  for (std::size_t i = 0; i < a.second.size(); ++i) EXPECT_EQ(a.second[i], b.second[i]);
}

TEST(Grasp, TheHandStallsAgainstTheTableWithItsForceBound) {
  const SceneSpec spec = parse("placement: packed\n");
  PhysicsWorld world(PhysicsOptions{});
  MeshCache meshes;
  build_scene(spec, 0, meshes, world);
  GripperOptions options;
  Eigen::Isometry3d pose = top_down(0.72, -0.12, spec.table.top_z_m + 0.08).X_FrameHand;
  Gripper gripper(world, options, pose);
  pose.translation().z() -= 0.1;  // fingertips 4 cm into the table
  gripper.move_to(pose);
  world.step(240);
  const double fingertips = gripper.actual_pose().translation().z() - options.geometry.depth_m;
  EXPECT_GT(fingertips, spec.table.top_z_m - 0.005);
  EXPECT_FALSE(gripper.touching(0.002).empty());
}

TEST(Grasp, ResetRestoresTheScene) {
  BulletCell cell = cylinder_cell(0.05);
  const Hand hand = top_down(0.72, -0.12, top_of_cylinder(cell) + 0.005);
  ASSERT_EQ(execute(cell, hand).outcome, GraspOutcome::kSuccess);
  cell.reset(0);
  EXPECT_EQ(cell.objects().size(), 1u);
  EXPECT_EQ(execute(cell, hand).outcome, GraspOutcome::kSuccess);
}

}  // namespace
}  // namespace antipode::cells
