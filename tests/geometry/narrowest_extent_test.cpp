// narrowest_horizontal_extent_m: known widths of boxes, a disc and degenerate sets.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "antipode/geometry/narrowest_extent.hpp"

namespace antipode {
namespace {

// The corners of a box of `size_m` turned by `yaw_rad` about z, then by `roll_rad` about x,
// and moved to `at_m`.
std::vector<Eigen::Vector3d> box_corners(const Eigen::Vector3d& size_m, double yaw_rad,
                                         double roll_rad = 0.0,
                                         const Eigen::Vector3d& at_m = Eigen::Vector3d::Zero()) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d c((i & 1 ? 0.5 : -0.5) * size_m.x(), (i & 2 ? 0.5 : -0.5) * size_m.y(),
                            (i & 4 ? 0.5 : -0.5) * size_m.z());
    corners.push_back(at_m + r * c);
  }
  return corners;
}

TEST(NarrowestExtent, ABoxLyingFlatIsAsWideAsItsShorterSideWhateverItsYaw) {
  // A sugar box (9.4 x 17.6 x 4.9 cm) lying on its broad face: 9.4 cm from any yaw.
  for (const double yaw_deg : {0.0, 17.0, 45.0, 90.0, 133.0}) {
    EXPECT_NEAR(
        narrowest_horizontal_extent_m(box_corners({0.094, 0.176, 0.049}, yaw_deg * M_PI / 180.0)),
        0.094, 1e-6)
        << yaw_deg;
  }
  // Stood on its side (rolled a quarter turn about x): its 4.9 cm thickness is horizontal.
  EXPECT_NEAR(narrowest_horizontal_extent_m(box_corners({0.094, 0.176, 0.049}, 0.3, M_PI / 2)),
              0.049, 1e-6);
  // Far from the origin, the same.
  EXPECT_NEAR(narrowest_horizontal_extent_m(
                  box_corners({0.094, 0.176, 0.049}, 0.7, 0.0, {12.0, -30.0, 0.5})),
              0.094, 1e-6);
}

TEST(NarrowestExtent, ATiltedBoxIsWiderThanItsSide) {
  // A 5 cm cube leaning 30 degrees about x: across y it spans 5 cos 30 + 5 sin 30 = 6.83 cm,
  // across x still 5 cm.
  EXPECT_NEAR(narrowest_horizontal_extent_m(box_corners({0.05, 0.05, 0.05}, 0.0, M_PI / 6)), 0.05,
              1e-6);
  EXPECT_NEAR(narrowest_horizontal_extent_m(box_corners({0.08, 0.05, 0.05}, 0.0, M_PI / 6)),
              0.05 * (std::cos(M_PI / 6) + std::sin(M_PI / 6)), 1e-6);
}

TEST(NarrowestExtent, ADiscIsAsWideAsItsDiameter) {
  std::vector<Eigen::Vector3d> rim;
  for (int i = 0; i < 360; ++i)
    rim.emplace_back(0.033 * std::cos(i * M_PI / 180), 0.033 * std::sin(i * M_PI / 180), 0.0);
  EXPECT_NEAR(narrowest_horizontal_extent_m(rim), 0.066, 1e-5);
}

TEST(NarrowestExtent, PointsOnOneVerticalLineOrNoneHaveNoWidth) {
  EXPECT_EQ(narrowest_horizontal_extent_m({}), 0.0);
  EXPECT_EQ(narrowest_horizontal_extent_m({{0.1, 0.2, 0.0}, {0.1, 0.2, 0.5}}), 0.0);
  EXPECT_EQ(narrowest_horizontal_extent_m({{0, 0, 0}, {0.1, 0, 0}, {0.3, 0, 1}}), 0.0);
}

}  // namespace
}  // namespace antipode
