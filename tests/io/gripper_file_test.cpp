// Gripper files: the shipped ones read as documented, the sampler's `hand` parameter takes a
// file or a map, and bad files are one-line errors naming the file.
#include <gtest/gtest.h>

#include <string>

#include "antipode/core/error.hpp"
#include "antipode/io/gripper_file.hpp"
#include "support/error_of.hpp"
#include "temp_dir.hpp"

namespace antipode {
namespace {

const std::string kGrippers = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/grippers/";

// Every field of two geometries, compared by name so that a failure says which.
void expect_same(const HandGeometry& a, const HandGeometry& b) {
  EXPECT_DOUBLE_EQ(a.finger_width_m, b.finger_width_m);
  EXPECT_DOUBLE_EQ(a.outer_diameter_m, b.outer_diameter_m);
  EXPECT_DOUBLE_EQ(a.depth_m, b.depth_m);
  EXPECT_DOUBLE_EQ(a.height_m, b.height_m);
  EXPECT_DOUBLE_EQ(a.init_bite_m, b.init_bite_m);
  EXPECT_DOUBLE_EQ(a.min_aperture_m, b.min_aperture_m);
  EXPECT_DOUBLE_EQ(a.max_aperture_m, b.max_aperture_m);
  EXPECT_DOUBLE_EQ(a.palm_thickness_m, b.palm_thickness_m);
}

// The Baxter file and HandGeometry's defaults describe the same gripper: the shipped model
// and every tree without a `hand` rely on the defaults.
TEST(GripperFile, TheBaxterFileIsTheDefaultGripper) {
  const GripperFile baxter = read_gripper_file(kGrippers + "baxter_electric.yaml");
  EXPECT_EQ(baxter.name, "Baxter gripper");
  expect_same(baxter.geometry, HandGeometry{});
}

TEST(GripperFile, TheEightCentimetreGripper) {
  const GripperFile g = read_gripper_file(kGrippers + "parallel_8cm.yaml");
  EXPECT_EQ(g.name, "8 cm gripper");
  EXPECT_DOUBLE_EQ(g.geometry.max_aperture_m, 0.08);
  EXPECT_DOUBLE_EQ(g.geometry.depth_m, 0.05);
  EXPECT_LT(g.geometry.min_aperture_m, 0.01);
}

class GripperFileErrors : public ::testing::Test {
 protected:
  std::string error_of_file(const std::string& yaml) {
    const std::string path = dir_.file("g.yaml");
    testing::write_bytes(path, yaml);
    return testing::error_of([&] { read_gripper_file(path); });
  }
  std::string path() const { return dir_.file("g.yaml"); }

  testing::TempDir dir_;
};

constexpr const char* kComplete =
    "finger_width_m: 0.01\nouter_diameter_m: 0.1\ndepth_m: 0.05\nheight_m: 0.02\n"
    "init_bite_m: 0.01\nmin_aperture_m: 0.002\nmax_aperture_m: 0.08\npalm_thickness_m: 0.02\n";

TEST_F(GripperFileErrors, OneLineNamingTheFile) {
  EXPECT_EQ(error_of_file(kComplete), "");
  EXPECT_EQ(testing::error_of([] { read_gripper_file("/no/such/gripper.yaml"); }),
            "gripper file '/no/such/gripper.yaml': no such file");
  EXPECT_EQ(error_of_file(""),
            "gripper file '" + path() + "': the file is empty (see robots/grippers/)");
  EXPECT_EQ(error_of_file("[0.08]"),
            "gripper file '" + path() + "': not a map of gripper fields (see robots/grippers/)");
  EXPECT_EQ(error_of_file("depth_m: 0.05"),
            path() + ":1:1: missing required parameter 'finger_width_m'");
  EXPECT_EQ(error_of_file(std::string(kComplete) + "max_aperture: 0.08\n"),
            path() + ":9:1: unknown parameter 'max_aperture' of gripper file '" + path() +
                "' (did you mean 'max_aperture_m'?)");
  std::string wide = kComplete;
  wide.replace(wide.find("max_aperture_m: 0.08"), 20, "max_aperture_m: 0.20");
  EXPECT_EQ(error_of_file(wide),
            path() +
                ":1:1: hand geometry: max_aperture_m + 2 * finger_width_m exceeds "
                "outer_diameter_m");
  std::string text = kComplete;
  text.replace(text.find("depth_m: 0.05"), 13, "depth_m: deep");
  EXPECT_EQ(error_of_file(text), path() + ":3:1: parameter 'depth_m' of gripper file '" + path() +
                                     "' must be a number, got 'deep'");
}

// A component's `hand`: a map whose absent fields keep Baxter's, or a gripper file found
// from the tree's folder or its parent, as models and scenes are.
TEST(HandGeometryParameter, AMapOrAFile) {
  const auto params = [](const std::string& yaml) {
    return Parameters(YAML::Load(yaml), "component 'sampler'",
                      std::string(ANTIPODE_TEST_SOURCE_DIR) + "/trees/detect.yaml");
  };
  expect_same(hand_geometry_parameter(params("samples: 3"), "hand"), HandGeometry{});
  HandGeometry deeper;
  deeper.depth_m = 0.07;
  expect_same(hand_geometry_parameter(params("hand: {depth_m: 0.07}"), "hand"), deeper);
  expect_same(hand_geometry_parameter(params("hand: robots/grippers/parallel_8cm.yaml"), "hand"),
              read_gripper_file(kGrippers + "parallel_8cm.yaml").geometry);
  const std::string missing = testing::error_of(
      [&] { hand_geometry_parameter(params("hand: robots/grippers/none.yaml"), "hand"); });
  EXPECT_NE(missing.find("trees/detect.yaml:1:1: gripper file '"), std::string::npos) << missing;
  EXPECT_NE(missing.find("none.yaml': no such file"), std::string::npos) << missing;
}

}  // namespace
}  // namespace antipode
