// The clutter box's description: its walls as solid boxes and as fixtures of the scene stage
// (grown 4 mm into the box, 1 cm elsewhere), and the errors of `bin:` parameters.
#include "antipode/geometry/bin.hpp"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

// The box of trees/clear_box.yaml: inner faces at x 0.44 / 0.74 and y -0.35 / -0.05.
Bin clear_box() {
  Bin bin;
  bin.center_m = {0.59, -0.20};
  bin.inner_size_m = {0.30, 0.30};
  bin.floor_z_m = -0.295;
  bin.wall_height_m = 0.06;
  bin.wall_thickness_m = 0.01;
  return bin;
}

int walls_containing(const Bin& bin, const Eigen::Vector3d& p) {
  const auto walls = bin.walls();
  return int(std::count_if(walls.begin(), walls.end(),
                           [&](const Eigen::AlignedBox3d& w) { return w.contains(p); }));
}

bool in_fixture(const std::vector<AxisBox>& fixtures, const Eigen::Vector3d& p) {
  return std::any_of(fixtures.begin(), fixtures.end(),
                     [&](const AxisBox& b) { return b.contains(p.cast<float>()); });
}

TEST(Bin, WallsRingTheInnerSizeWithoutOverlapping) {
  const Bin bin = clear_box();
  const double z = -0.27;  // half way up the walls
  EXPECT_EQ(walls_containing(bin, {0.59, -0.20, z}), 0) << "the box's middle";
  EXPECT_EQ(walls_containing(bin, {0.441, -0.20, z}), 0) << "1 mm inside the -x wall";
  EXPECT_EQ(walls_containing(bin, {0.435, -0.20, z}), 1) << "in the -x wall";
  EXPECT_EQ(walls_containing(bin, {0.745, -0.20, z}), 1) << "in the +x wall";
  EXPECT_EQ(walls_containing(bin, {0.59, -0.355, z}), 1) << "in the -y wall";
  EXPECT_EQ(walls_containing(bin, {0.59, -0.045, z}), 1) << "in the +y wall";
  EXPECT_EQ(walls_containing(bin, {0.4301, -0.3599, z}), 1) << "a corner: the -y wall's";
  EXPECT_EQ(walls_containing(bin, {0.435, -0.20, -0.23}), 0) << "above the wall's top";
  EXPECT_EQ(walls_containing(bin, {0.425, -0.20, z}), 0) << "outside the outer face";
}

TEST(Bin, FixturesReach4mmIntoTheBoxAnd1cmBeyondTheWalls) {
  const std::vector<AxisBox> fixtures = clear_box().fixtures(0.004, 0.01);
  ASSERT_EQ(fixtures.size(), 4u);
  const double z = -0.27;
  EXPECT_TRUE(in_fixture(fixtures, {0.443, -0.20, z})) << "3 mm inside the -x wall";
  EXPECT_FALSE(in_fixture(fixtures, {0.445, -0.20, z})) << "5 mm inside the -x wall";
  EXPECT_TRUE(in_fixture(fixtures, {0.737, -0.20, z})) << "3 mm inside the +x wall";
  EXPECT_FALSE(in_fixture(fixtures, {0.735, -0.20, z}));
  EXPECT_TRUE(in_fixture(fixtures, {0.59, -0.347, z})) << "3 mm inside the -y wall";
  EXPECT_FALSE(in_fixture(fixtures, {0.59, -0.345, z}));
  EXPECT_TRUE(in_fixture(fixtures, {0.59, -0.053, z})) << "3 mm inside the +y wall";
  EXPECT_FALSE(in_fixture(fixtures, {0.59, -0.055, z}));
  EXPECT_TRUE(in_fixture(fixtures, {0.421, -0.20, z})) << "9 mm outside the -x wall";
  EXPECT_FALSE(in_fixture(fixtures, {0.419, -0.20, z})) << "11 mm outside";
  EXPECT_TRUE(in_fixture(fixtures, {0.435, -0.20, -0.226})) << "9 mm above the top";
  EXPECT_FALSE(in_fixture(fixtures, {0.435, -0.20, -0.224})) << "11 mm above the top";
  EXPECT_FALSE(in_fixture(fixtures, {0.59, -0.20, -0.29})) << "the box's floor";
}

std::string read_error(const std::string& yaml) {
  try {
    read_bin(Parameters(YAML::Load(yaml), "component 'selector'", "tree.yaml"));
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(Bin, ReadsItsParametersAndNamesTheBadOne) {
  const Bin bin = read_bin(Parameters(
      YAML::Load("{center_m: [0.59, -0.2], inner_size_m: [0.3, 0.2], floor_z_m: -0.295}"),
      "component 'selector'", "tree.yaml"));
  EXPECT_EQ(bin.inner_size_m, Eigen::Vector2d(0.3, 0.2));
  EXPECT_EQ(bin.floor_z_m, -0.295);
  EXPECT_EQ(bin.wall_height_m, 0.06) << "the default";
  EXPECT_NE(read_error("{inner_size_m: [0.3, 0.3]}").find("missing required parameter 'center_m'"),
            std::string::npos);
  EXPECT_NE(read_error("{center_m: [0, 0, 0], inner_size_m: [0.3, 0.3]}")
                .find("'center_m' needs two numbers [x, y]"),
            std::string::npos);
  EXPECT_NE(read_error("{center_m: [0, 0], inner_size_m: [0, 0.3]}")
                .find("'inner_size_m' must be in (0, 10] m"),
            std::string::npos);
  EXPECT_NE(read_error("{center_m: [0, 0], inner_size_m: [0.3, 0.3], wall_height_m: 0}")
                .find("parameter 'wall_height_m' must be in [0.001, 2], got 0"),
            std::string::npos);
  EXPECT_NE(read_error("{center_m: [0, 0], inner_size_m: [0.3, 0.3], wall_hight_m: 0.1}")
                .find("did you mean 'wall_height_m'"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode
