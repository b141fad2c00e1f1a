// The cell's workspace: the objects objects_left() counts are those on the table and, in a
// scene that keeps its box, inside the box's walls.
#include <gtest/gtest.h>

#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/cell.hpp"
#include "bullet_cell.hpp"

namespace antipode::cells {
namespace {

SceneSpec parse(const std::string& yaml) {
  return parse_scene(Parameters(YAML::Load(yaml), "scene 'test.yaml'", "test.yaml"));
}

// The dense-clutter box (inner faces at x 0.44 / 0.74, y -0.35 / -0.05) and two cylinders:
// one in the box, one on the table 10 cm beside it.
const char* const kBoxAndTwoCylinders = R"(
box: { center_m: [0.59, -0.20], inner_size_m: [0.30, 0.30], wall_height_m: 0.06 }
placement: packed
objects:
  - { shape: cylinder, size_m: [0.05, 0.1], position_m: [0.59, -0.20] }
  - { shape: cylinder, size_m: [0.05, 0.1], position_m: [0.59, 0.10] }
)";

TEST(CellWorkspace, AnObjectBesideTheBoxIsNotLeftInIt) {
  const BulletCell cell(parse(kBoxAndTwoCylinders), CellOptions{});
  ASSERT_EQ(cell.objects().size(), 2u) << "both rest on the table";
  EXPECT_EQ(*cell.objects_left(), 1);
  const std::vector<ObjectTruth> truth = cell.object_truth();
  ASSERT_EQ(truth.size(), 1u);
  EXPECT_NEAR(truth[0].X_BaseObject.translation().y(), -0.20, 0.01) << "the one in the box";
  // Both were placed: the one beside the box is what a run reports as missed while filling.
  EXPECT_EQ(cell.objects_placed(), 2);
}

TEST(CellWorkspace, WithoutABoxTheWholeTableIsTheWorkspace) {
  std::string yaml = kBoxAndTwoCylinders;
  yaml.replace(yaml.find("box:"), yaml.find('\n', yaml.find("box:")) - yaml.find("box:"),
               "# no box");
  const BulletCell cell(parse(yaml), CellOptions{});
  EXPECT_EQ(*cell.objects_left(), 2);
  EXPECT_EQ(cell.object_truth().size(), 2u);
}

// A training pile (seed 500025 of scenes/train_pile_wide.yaml) in which a box object came to
// rest on the box's wall, its centre above the wall (y -0.046; the inner face is at -0.05):
// picking the bottle beside it (a hand from that scene's outcome trials) tips it out. The
// pick succeeds, and its record names what left the box with it. The pile settles so with
// gcc's floating-point code; scripts/sanitize's clang build leaves this test out.
TEST(CellWorkspace, ASuccessfulPickNamesWhatLeftTheBoxWithIt) {
  CellOptions options;
  options.seed = 500025;
  BulletCell cell(
      read_scene(std::string(ANTIPODE_TEST_SOURCE_DIR) + "/scenes/train_pile_wide.yaml"), options);
  const int before = *cell.objects_left();
  Hand hand;
  hand.X_FrameHand.linear() = Eigen::Quaterniond(0.6623691947901749, -0.311769605226703,
                                                 0.660901767528287, -0.16515329843450863)
                                  .normalized()
                                  .toRotationMatrix();
  hand.X_FrameHand.translation() << 0.6645656271948656, -0.11518197061050445, -0.19136560370377056;
  const GraspAttempt record = cell.execute(GraspRequest{hand, HandGeometry{}, {}});
  ASSERT_EQ(record.outcome, GraspOutcome::kSuccess) << record.reason;
  EXPECT_NE(record.reason.find("; out of the workspace with it: box (out of the box)"),
            std::string::npos)
      << record.reason;
  EXPECT_EQ(*cell.objects_left(), before - 2) << "the bottle picked, the box out of the box";
}

}  // namespace
}  // namespace antipode::cells
