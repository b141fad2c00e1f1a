// Planning scenes: the shipped MotionBenchMaker transcriptions read, a problem's goal is the
// hand at the stated standoff from its target, the variations follow their stated spread,
// the same seed gives the same problem, and bad files give located errors.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "antipode/evaluation/planning_problems.hpp"
#include "support/error_of.hpp"

namespace antipode::evaluation {
namespace {

namespace fs = std::filesystem;
using ::antipode::testing::error_of;

std::string source(const std::string& path) {
  return std::string(ANTIPODE_TEST_SOURCE_DIR) + "/" + path;
}

// This process's scratch folder, removed with its files when the tests end.
struct ScratchFolder {
  fs::path path =
      fs::temp_directory_path() / ("antipode_planning_scene_" + std::to_string(::getpid()));
  ScratchFolder() { fs::create_directories(path); }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

// A scene file in the scratch folder (each call replaces the last).
std::string scene_file(const std::string& text) {
  static const ScratchFolder folder;
  const fs::path path = folder.path / "scene.yaml";
  std::ofstream(path) << text;
  return path.string();
}

const char* kBox = R"(objects:
  - { name: Can1, cylinder: { radius_m: 0.03, length_m: 0.14 }, position_m: [0.8, 0.0, 0.55] }
  - { name: lid, box_m: [0.7, 0.7, 0.04], position_m: [0.9, 0.0, 1.35], quaternion_xyzw: [0, 0.383, 0, 0.924] }
targets: [Can1]
approach: down
standoff_m: 0.15
robots:
  panda: { frame: panda_link0, offset_m: [-0.15, 0.0, -1.02] }
)";

TEST(PlanningScene, EveryShippedSceneReadsWithItsObjectsAndTargets) {
  const std::pair<const char*, std::size_t> scenes[] = {
      {"scenes/planning/mbm_table_pick.yaml", 12},
      {"scenes/planning/mbm_box.yaml", 7},
      {"scenes/planning/mbm_cage.yaml", 8},
      {"scenes/planning/mbm_bookshelf_tall.yaml", 15},
      {"scenes/planning/mbm_bookshelf_thin.yaml", 21},
      {"scenes/planning/mbm_bookshelf_small.yaml", 7}};
  for (const auto& [path, objects] : scenes) {
    const PlanningScene scene = read_planning_scene(source(path));
    EXPECT_EQ(scene.objects.size(), objects) << path;
    EXPECT_FALSE(scene.targets.empty()) << path;
    EXPECT_EQ(planning_frame(scene, "panda"), "panda_link0") << path;
    EXPECT_EQ(planning_frame(scene, "baxter"), "right_arm_mount") << path;
  }
}

TEST(PlanningScene, TheExampleInRobotMdReads) {
  std::ifstream in(source("docs/robot.md"));
  std::string line, text;
  bool after = false, inside = false;
  while (std::getline(in, line)) {
    if (line == "A planning scene file:") after = true;
    if (after && !inside && line == "```yaml") {
      inside = true;
    } else if (inside && line == "```") {
      break;
    } else if (inside) {
      text += line + "\n";
    }
  }
  ASSERT_FALSE(text.empty());
  const PlanningScene scene = read_planning_scene(scene_file(text));
  EXPECT_EQ(scene.objects.size(), 2U);
  EXPECT_TRUE(scene.approach_down);
  EXPECT_EQ(planning_frame(scene, "panda"), "panda_link0");
}

TEST(PlanningScene, TheGoalIsTheHandAtTheStandoffFromItsTarget) {
  const PlanningScene scene = read_planning_scene(scene_file(kBox));
  Eigen::Isometry3d X_BaseFrame = Eigen::Isometry3d::Identity();
  X_BaseFrame.translation() = Eigen::Vector3d(0.1, -0.2, -0.295);
  const PlanningQuery q = sample_planning_query(scene, "panda", X_BaseFrame, 7);
  ASSERT_EQ(q.obstacles.size(), 2U);
  EXPECT_EQ(q.target, "Can1");
  const Eigen::Vector3d can = Eigen::Vector3d(0.8 - 0.15 + 0.1, -0.2, 0.55 - 1.02 - 0.295);
  EXPECT_LT((q.obstacles[0].X_BaseObstacle.translation() - can).norm(), 1e-12);
  EXPECT_EQ(q.obstacles[0].shape, Obstacle::Shape::kCylinder);
  EXPECT_DOUBLE_EQ(q.obstacles[0].size_m.x(), 0.03);
  // Down: the approach (x) along -z, the hand 15 cm above the can's centre.
  EXPECT_LT((q.X_BaseHand.linear().col(0) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  EXPECT_LT((q.X_BaseHand.translation() - (can + Eigen::Vector3d(0, 0, 0.15))).norm(), 1e-12);
  // The lid keeps its 45 degree tilt.
  const Eigen::Vector3d lid_z = q.obstacles[1].X_BaseObstacle.linear().col(2);
  EXPECT_NEAR(std::acos(lid_z.z()), M_PI / 4, 2e-3);
}

TEST(PlanningScene, VariationsFollowTheirStatedSpreadAndTheSeed) {
  const PlanningScene scene = read_planning_scene(source("scenes/planning/mbm_box.yaml"));
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  // The base (not varied itself) moves with the world: normal, 0.1 m along z.
  double sum = 0.0, sum2 = 0.0, max_turn = 0.0;
  const int n = 4000;
  for (int seed = 0; seed < n; ++seed) {
    const PlanningQuery q = sample_planning_query(scene, "panda", I, std::uint64_t(seed));
    const Eigen::Isometry3d& base = q.obstacles[1].X_BaseObstacle;
    const double dz = base.translation().z() - (0.44 - 1.02);
    sum += dz;
    sum2 += dz * dz;
    max_turn = std::max(max_turn, std::abs(std::atan2(base.linear()(1, 0), base.linear()(0, 0))));
  }
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.01);
  EXPECT_NEAR(sigma, 0.1, 0.01);
  EXPECT_LE(max_turn, 1.57 + 1e-9);
  EXPECT_GT(max_turn, 1.5);
  const PlanningQuery a = sample_planning_query(scene, "panda", I, 42);
  const PlanningQuery b = sample_planning_query(scene, "panda", I, 42);
  EXPECT_TRUE(a.X_BaseHand.isApprox(b.X_BaseHand, 0.0));
}

TEST(PlanningScene, BadFilesGiveLocatedErrors) {
  const auto error = [](const std::string& text) {
    return error_of([&] { read_planning_scene(scene_file(text)); });
  };
  std::string text = kBox;
  EXPECT_NE(error(text + "colour: red\n").find("colour"), std::string::npos);
  const std::string no_shape =
      std::string(kBox).replace(std::string(kBox).find("box_m: [0.7, 0.7, 0.04], "), 26, "");
  EXPECT_NE(error(no_shape).find("object 'lid' needs one shape"), std::string::npos)
      << error(no_shape);
  const std::string bad_target =
      std::string(kBox).replace(std::string(kBox).find("[Can1]"), 6, "[Can2]");
  EXPECT_NE(error(bad_target).find("targets: no object 'Can2'"), std::string::npos);
  const std::string bad_approach =
      std::string(kBox).replace(std::string(kBox).find("approach: down"), 14, "approach: up");
  EXPECT_NE(error(bad_approach).find("approach must be front or down, got 'up'"),
            std::string::npos);
  const PlanningScene scene = read_planning_scene(scene_file(kBox));
  EXPECT_NE(error_of([&] {
              planning_frame(scene, "ur5e");
            }).find("places no robot 'ur5e' (it places panda)"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode::evaluation
