// Depth scale corrected against a support of known height: two views of a table with a box
// on it, each view's depths off by its own factor, come back to the table's height.
#include "antipode/geometry/depth_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

constexpr double kTableZ = -0.295;

// A table top (z = kTableZ, 0.6 m square around (0.7, -0.1)) and a 10 cm box on it, seen from
// `origin` as view `v`, with every point's distance from the origin multiplied by `gain`.
void add_view(Cloud& cloud, const Eigen::Vector3f& origin, std::uint32_t v, float gain) {
  const auto add = [&](const Eigen::Vector3f& p) {
    cloud.points_m.push_back(origin + gain * (p - origin));
    cloud.view_masks.push_back(1u << v);
  };
  for (float x = 0.4f; x <= 1.0f; x += 0.005f)
    for (float y = -0.4f; y <= 0.2f; y += 0.005f) {
      const bool under_box = std::abs(x - 0.7f) < 0.05f && std::abs(y + 0.1f) < 0.05f;
      add(Eigen::Vector3f(x, y, under_box ? float(kTableZ) + 0.1f : float(kTableZ)));
    }
  cloud.view_origins_m.push_back(origin);
}

TEST(DepthScale, EachViewsSupportReturnsToItsKnownHeight) {
  Cloud cloud;
  add_view(cloud, Eigen::Vector3f(1.2f, -0.1f, 0.005f), 0, 1.03f);
  add_view(cloud, Eigen::Vector3f(0.4f, 0.5f, 0.25f), 1, 0.97f);
  DepthScaleOptions options;
  options.support_height_m = kTableZ;
  const std::vector<ViewScale> views = correct_depth_scale(cloud, options, RandomStream(3));
  ASSERT_EQ(views.size(), 2u);
  EXPECT_TRUE(views[0].corrected && views[1].corrected);
  EXPECT_NEAR(views[0].factor, 1.0 / 1.03, 1e-4);
  EXPECT_NEAR(views[1].factor, 1.0 / 0.97, 1e-4);
  EXPECT_LT(views[0].seen_height_m, kTableZ - 0.005);  // a longer depth: seen lower
  // Every point is back where it was: table points at the table's height, the box's top 10 cm
  // above it.
  double worst = 0.0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const double z = cloud.points_m[i].z();
    worst = std::max(worst, std::min(std::abs(z - kTableZ), std::abs(z - kTableZ - 0.1)));
  }
  EXPECT_LT(worst, 0.0005);
}

TEST(DepthScale, AViewWithoutASupportOrBeyondTheLimitIsLeftAlone) {
  Cloud cloud;
  add_view(cloud, Eigen::Vector3f(1.2f, -0.1f, 0.005f), 0, 1.25f);  // 25%: not a scale error
  const Cloud before = cloud;
  DepthScaleOptions options;
  options.support_height_m = kTableZ;
  const std::vector<ViewScale> views = correct_depth_scale(cloud, options, RandomStream(3));
  EXPECT_FALSE(views[0].corrected);
  EXPECT_EQ(cloud.points_m, before.points_m);
  cloud.view_origins_m.clear();
  EXPECT_THROW(correct_depth_scale(cloud, options, RandomStream(3)), Error);
}

}  // namespace
}  // namespace antipode
