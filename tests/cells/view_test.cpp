#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "antipode/core/parameters.hpp"
#include "bullet_cell.hpp"
#include "dexnet_noise.hpp"
#include "sensor_random.hpp"

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

TEST(View, DepthErrorsOnAFlatTableFollowTheAxialModel) {
  // A camera straight above the bare table: every return is at optical depth `depth`, its
  // height error is minus its axial error, and lateral errors stay horizontal.
  const SceneSpec spec = parse(R"(
placement: pile
cameras: { down: { position_m: [0.725, -0.135, 0.5], look_at_m: [0.725, -0.135, -0.295] } }
)");
  CellOptions ideal_options, noisy_options;
  ideal_options.sensor.scale = 0.0;
  BulletCell ideal(spec, ideal_options), noisy(spec, noisy_options);
  const Cloud reference = ideal.capture({"down"}), cloud = noisy.capture({"down"});
  // Incidence stays under 40 degrees here: no dropout, so no return is lost.
  EXPECT_EQ(cloud.size(), reference.size());
  const double top = spec.table.top_z_m, depth = 0.5 - top;
  const Eigen::Vector3d camera(0.725, -0.135, 0.5);
  const SensorModel model;
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0, beyond_two = 0;
  for (const auto& p : cloud.points_m) {
    const double error = p.z() - top;
    ASSERT_LT(std::abs(error), 0.02);
    const Eigen::Vector3d ray = p.cast<double>() - camera;
    const double theta = std::acos(-ray.z() / ray.norm());
    const double standard = error / model.axial_sigma_m(depth, theta);
    sum += standard;
    sum2 += standard * standard;
    beyond_two += std::abs(standard) > 2.0 ? 1 : 0;
    ++n;
  }
  ASSERT_GT(n, 250000u);
  EXPECT_NEAR(sum / double(n), 0.0, 0.01);
  EXPECT_NEAR(sum2 / double(n), 1.0, 0.02);
  EXPECT_NEAR(double(beyond_two) / double(n), 0.0455, 0.0025);  // P(|N(0,1)| > 2)
}

// Dex-Net's noise (GIGA's benchmark): over many images the gain has mean 1 and standard
// deviation 1 / sqrt(1000); within an image the additive field has a 5 mm deviation, is
// smooth between neighbouring pixels and independent far apart; the same seed gives the
// same noise; scale 0 is the ideal sensor.
TEST(DexNetNoise, GainAndFieldHaveTheModelsStatistics) {
  SensorModel model;
  model.kind = SensorKind::kDexNet;
  double gain_sum = 0.0, gain_sum2 = 0.0;
  const int images = 4000;
  for (int i = 0; i < images; ++i) {
    const double g = DexNetNoise(model, 64, 48, std::uint64_t(i)).gain();
    gain_sum += g, gain_sum2 += g * g;
  }
  const double mean = gain_sum / images, sd = std::sqrt(gain_sum2 / images - mean * mean);
  EXPECT_NEAR(mean, 1.0, 0.002);
  EXPECT_NEAR(sd, 1.0 / std::sqrt(1000.0), 0.002);

  const DexNetNoise noise(model, 640, 480, 7);
  double sum2 = 0.0, neighbour = 0.0, far = 0.0;
  int n = 0;
  for (int v = 0; v < 480; v += 4)
    for (int u = 0; u + 40 < 640; u += 4) {  // grid nodes: the field's own values
      const double f = noise.apply(0.0, u, v), g = noise.apply(0.0, u + 1, v);
      sum2 += f * f, neighbour += (f - g) * (f - g), far += f * noise.apply(0.0, u + 40, v);
      ++n;
    }
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.005, 0.0003);
  EXPECT_LT(std::sqrt(neighbour / n), 0.35 * 0.005);  // a quarter of the way to the next node
  EXPECT_NEAR(far / n, 0.0, 0.1 * 0.005 * 0.005);
  EXPECT_DOUBLE_EQ(noise.apply(0.5, 100, 100),
                   DexNetNoise(model, 640, 480, 7).apply(0.5, 100, 100));
  EXPECT_NE(noise.apply(0.5, 100, 100), DexNetNoise(model, 640, 480, 8).apply(0.5, 100, 100));
  model.scale = 0.0;
  EXPECT_EQ(DexNetNoise(model, 640, 480, 7).apply(0.5, 100, 100), 0.5);
}

TEST(SensorRandom, NormalsHaveTheMomentsAndTailsOfAStandardNormal) {
  SensorRandom random(5);
  const int n = 2000000;
  double s1 = 0, s2 = 0, s4 = 0;
  int above_one = 0, above_three = 0;
  for (int i = 0; i < n; ++i) {
    const double x = random.normal();
    s1 += x;
    s2 += x * x;
    s4 += x * x * x * x;
    above_one += x > 1.0 ? 1 : 0;
    above_three += std::abs(x) > 3.0 ? 1 : 0;
  }
  EXPECT_NEAR(s1 / n, 0.0, 0.003);
  EXPECT_NEAR(s2 / n, 1.0, 0.004);
  EXPECT_NEAR(s4 / n, 3.0, 0.03);
  EXPECT_NEAR(double(above_one) / n, 0.158655, 0.0015);
  EXPECT_NEAR(double(above_three) / n, 0.0026998, 0.0002);
  double lo = 1.0, hi = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double u = random.uniform();
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  EXPECT_GE(lo, 0.0);
  EXPECT_LT(hi, 1.0);
}

TEST(SensorRandom, SameSeedSameDrawsAndAccurateArcCosine) {
  SensorRandom a(9), b(9), c(10);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(a.normal(), b.normal());
  EXPECT_NE(a.normal(), c.normal());
  double worst = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double x = i / 100000.0;
    worst = std::max(worst, std::abs(fast_acos(x) - std::acos(x)));
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(View, UnknownViewIsAnError) {
  BulletCell cell = box_cell(0.0);
  EXPECT_THROW(cell.capture({"bottom"}), Error);
}

}  // namespace
}  // namespace antipode::cells
