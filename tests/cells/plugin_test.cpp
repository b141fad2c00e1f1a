#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "support/error_of.hpp"
#include "top_down_hand.hpp"

namespace antipode {
namespace {

class BulletCellPluginTest : public ::testing::Test {
 protected:
  BulletCellPluginTest() : host_(std::vector<std::string>{}) {
    host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" +
                       plugin_file_name("bullet_cell"));
  }

  // Parameters as if written in trees/test.yaml, so scene paths resolve from the project root.
  std::shared_ptr<Cell> create(const std::string& yaml) {
    const Parameters params(YAML::Load(yaml), "component 'cell'",
                            std::string(ANTIPODE_TEST_SOURCE_DIR) + "/trees/test.yaml");
    return std::dynamic_pointer_cast<Cell>(host_.create("bullet_cell", params));
  }

  std::string creation_error(const std::string& yaml) {
    return testing::error_of([&] { create(yaml); });
  }

  PluginHost host_;
};

using cells::testing::top_down;

TEST_F(BulletCellPluginTest, LoadsAsACell) {
  ASSERT_EQ(host_.records().size(), 1u);
  EXPECT_EQ(host_.records()[0].state, PluginRecord::State::kLoaded) << host_.records()[0].reason;
  EXPECT_EQ(host_.kind_of("bullet_cell"), ComponentKind::kCell);
}

TEST_F(BulletCellPluginTest, CapturesAndGraspsThroughTheInterface) {
  const auto cell = create("scene: scenes/isolated_cylinder.yaml\nnoise: 0.5\nseed: 3");
  ASSERT_NE(cell, nullptr);
  const auto names = cell->view_names();
  ASSERT_GE(names.size(), 2u);
  const Cloud cloud = cell->capture({names[0], names[1]});
  cloud.validate();
  EXPECT_EQ(cloud.view_origins_m.size(), 2u);
  EXPECT_GT(cloud.size(), 10000u);
  const Hand hand = top_down(0.72, -0.12, -0.295 + 0.1 + 0.005);
  const GraspRequest request{hand, HandGeometry{}, {}};
  EXPECT_EQ(cell->execute(request).outcome, GraspOutcome::kSuccess);
  EXPECT_EQ(cell->execute(request).outcome, GraspOutcome::kEmptyGrasp)
      << "the cylinder was removed";
  cell->reset(3);
  EXPECT_EQ(cell->execute(request).outcome, GraspOutcome::kSuccess);
}

TEST_F(BulletCellPluginTest, RejectsBadParameters) {
  EXPECT_NE(creation_error("scene: scenes/isolated_cylinder.yaml\nnoize: 1").find("did you mean"),
            std::string::npos);
  EXPECT_NE(creation_error("scene: scenes/isolated_cylinder.yaml\nnoise: -1").find("noise"),
            std::string::npos);
  EXPECT_NE(creation_error("scene: scenes/isolated_cylinder.yaml\nexecution_noise_m: 0.5")
                .find("'execution_noise_m' must be in [0.000000, 0.050000]"),
            std::string::npos);
  EXPECT_NE(creation_error("scene: scenes/no_such_scene.yaml").find("no_such_scene"),
            std::string::npos);
  EXPECT_NE(creation_error("noise: 1").find("scene"), std::string::npos);
  EXPECT_NE(creation_error("scene: scenes/isolated_cylinder.yaml\nobjects: /no/such/folder")
                .find("is not a folder of object meshes"),
            std::string::npos);
}

TEST_F(BulletCellPluginTest, RejectsBadArmParametersAtTheirKey) {
  const std::string scene = "scene: scenes/isolated_cylinder.yaml\n";
  EXPECT_NE(creation_error(scene + "robot: robots/nope.yaml").find("robot: robot file"),
            std::string::npos);
  EXPECT_NE(creation_error(scene + "robot: robots/baxter/baxter.urdf")
                .find("a URDF, not a robot file (name the robot file that names this URDF"),
            std::string::npos);
  const std::string home =
      creation_error(scene + "robot: robots/baxter/baxter.yaml\n" + "home_rad: [0, 1]");
  EXPECT_NE(home.find("home_rad: 2 values for the 7 joints of the arm (right_s0 ... right_w2)"),
            std::string::npos)
      << home;
  EXPECT_NE(home.find("test.yaml:3:"), std::string::npos) << home;  // the home_rad line
  EXPECT_NE(creation_error(scene + "home_rad: [0, 1]").find("'home_rad' needs 'robot'"),
            std::string::npos);
}

TEST_F(BulletCellPluginTest, ObjectsFolderReplacesTheScenesObjects) {
  const std::string ycb = std::string(ANTIPODE_TEST_DATA_DIR) + "/objects/ycb";
  if (!std::filesystem::is_directory(ycb)) GTEST_SKIP() << "no " << ycb;
  const std::string scene = "scene: scenes/isolated_cylinder.yaml\nnoise: 0\nseed: 3\n";
  const auto cylinder = create(scene);
  const auto replaced = create(scene + "objects: " + ycb);
  const auto names = cylinder->view_names();
  // Points above the table top (z = -0.295) belong to the object.
  const auto object_points = [&](Cell& cell) {
    const Cloud cloud = cell.capture({names[0]});
    return std::count_if(cloud.points_m.begin(), cloud.points_m.end(),
                         [](const Eigen::Vector3f& p) { return p.z() > -0.285f; });
  };
  const auto cylinder_points = object_points(*cylinder);
  const auto ycb_points = object_points(*replaced);
  EXPECT_GT(ycb_points, 100);
  EXPECT_NE(cylinder_points, ycb_points);
  // The same seed draws the same YCB object again.
  EXPECT_EQ(object_points(*create(scene + "objects: " + ycb)), ycb_points);
}

}  // namespace
}  // namespace antipode
