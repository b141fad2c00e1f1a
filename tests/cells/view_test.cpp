#include <gtest/gtest.h>

#include <chrono>

#include "antipode/core/parameters.hpp"
#include "bullet_cell.hpp"

namespace antipode::cells {
namespace {

SceneSpec parse(const std::string& yaml) {
  return parse_scene(Parameters(YAML::Load(yaml), "scene 'test.yaml'", "test.yaml"));
}

// A 6 x 8 x 10 cm box resting on the table at (0.72, -0.12).
BulletCell box_cell(double noise) {
  CellOptions options;
  options.sensor.scale = noise;
  return BulletCell(parse(R"(
placement: isolated
objects:
  - { shape: box, size_m: [0.06, 0.08, 0.10], position_m: [0.72, -0.12] }
)"),
                    options);
}

// Counts the points of `cloud` within `tolerance` of the box's volume.
int points_on_box(const Cloud& cloud, double top_z, double tolerance) {
  const Eigen::AlignedBox3d box(Eigen::Vector3d(0.69, -0.16, top_z),
                                Eigen::Vector3d(0.75, -0.08, top_z + 0.10));
  int n = 0;
  for (const auto& p : cloud.points_m)
    if (box.exteriorDistance(p.cast<double>()) <= tolerance && p.z() > top_z + 0.005) ++n;
  return n;
}

TEST(View, IdealViewSeesTheBoxExactly) {
  BulletCell cell = box_cell(0.0);
  const Cloud cloud = cell.capture({"left"});
  cloud.validate();
  ASSERT_EQ(cloud.view_origins_m.size(), 1u);
  const double top = cell.scene().table.top_z_m;
  int above_table = 0;
  for (const auto& p : cloud.points_m)
    if (p.z() > top + 0.005) ++above_table;
  EXPECT_GT(above_table, 500);
  EXPECT_EQ(points_on_box(cloud, top, 0.001), above_table);
}

TEST(View, NoisyTwoViewCloudKeepsViewsApartAndNearTheBox) {
  BulletCell cell = box_cell(1.0);
  const Cloud cloud = cell.capture({"left", "right"});
  cloud.validate();
  ASSERT_EQ(cloud.view_origins_m.size(), 2u);
  int per_view[2] = {0, 0};
  for (auto mask : cloud.view_masks) {
    ASSERT_TRUE(mask == 1u || mask == 2u);
    ++per_view[mask - 1];
  }
  EXPECT_GT(per_view[0], 10000);
  EXPECT_GT(per_view[1], 10000);
  const double top = cell.scene().table.top_z_m;
  int above = 0;
  for (const auto& p : cloud.points_m)
    if (p.z() > top + 0.02) ++above;
  EXPECT_GT(points_on_box(cloud, top, 0.015), above * 95 / 100);
}

TEST(View, SameSeedSameCloud) {
  BulletCell a = box_cell(1.0), b = box_cell(1.0);
  const Cloud x = a.capture({"right"}), y = b.capture({"right"});
  ASSERT_EQ(x.size(), y.size());
  for (std::size_t i = 0; i < x.size(); i += 97) EXPECT_EQ(x.points_m[i], y.points_m[i]);
}

TEST(View, SameCloudForAnyThreadCount) {
  CellOptions one, two;
  one.render_threads = 1;
  two.render_threads = 3;
  const std::string yaml = "placement: pile\nrandom_objects: { count: 3, shapes: [box, sphere] }\n";
  BulletCell a(parse(yaml), one), b(parse(yaml), two);
  const Cloud x = a.capture({"left", "top"}), y = b.capture({"left", "top"});
  ASSERT_EQ(x.size(), y.size());
  EXPECT_EQ(x.points_m, y.points_m);
  EXPECT_EQ(x.view_masks, y.view_masks);
}

TEST(View, UnknownViewIsAnError) {
  BulletCell cell = box_cell(0.0);
  EXPECT_THROW(cell.capture({"bottom"}), Error);
}

}  // namespace
}  // namespace antipode::cells
