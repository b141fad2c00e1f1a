#include "antipode/geometry/hand_body.hpp"

#include <gtest/gtest.h>

namespace antipode {
namespace {

TEST(HandBodyTest, BoxesFollowTheHandGeometry) {
  const HandGeometry geometry;  // Baxter defaults
  const HandBody body = make_hand_body(geometry, 0.01);
  EXPECT_TRUE(body.finger_plus_y.min_m.isApprox(Eigen::Vector3d(0, 0.036, -0.01)));
  EXPECT_TRUE(body.finger_plus_y.max_m.isApprox(Eigen::Vector3d(0.06, 0.046, 0.01)));
  EXPECT_TRUE(body.finger_minus_y.min_m.isApprox(Eigen::Vector3d(0, -0.046, -0.01)));
  EXPECT_TRUE(body.palm.min_m.isApprox(Eigen::Vector3d(-0.01, -0.046, -0.01)));
  EXPECT_TRUE(body.palm.max_m.isApprox(Eigen::Vector3d(0, 0.046, 0.01)));
  EXPECT_TRUE(body.in_closing_region({0.03, 0.0, 0.0}));
  EXPECT_FALSE(body.in_closing_region({0.03, 0.036, 0.0}));  // on the finger's face
  EXPECT_TRUE(body.collides({0.03, 0.036, 0.0}));
  EXPECT_TRUE(body.collides({-0.005, 0.0, 0.0}));    // palm
  EXPECT_FALSE(body.collides({0.03, 0.0, 0.0}));     // between the fingers
  EXPECT_FALSE(body.collides({0.061, 0.04, 0.0}));   // beyond the fingertip
  EXPECT_FALSE(body.collides({0.03, 0.04, 0.011}));  // above the finger
}

TEST(HandBodyTest, PointTestsUseThePose) {
  const HandBody body = make_hand_body(HandGeometry{}, 0.01);
  Eigen::Isometry3d X_FrameHand = Eigen::Isometry3d::Identity();
  // Approach along -z, closing along +x, axis along -y (right-handed).
  X_FrameHand.linear() << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  X_FrameHand.translation() = Eigen::Vector3d(0.1, 0.2, 0.8);
  ASSERT_NEAR(X_FrameHand.linear().determinant(), 1.0, 1e-12);
  const std::vector<Eigen::Vector3f> points = {
      {0.1f, 0.2f, 0.77f},   // 3 cm ahead of the palm: closing region
      {0.14f, 0.2f, 0.77f},  // 4 cm along closing: finger
      {0.1f, 0.2f, 0.805f},  // behind the palm face: palm
      {0.1f, 0.2f, 0.70f}};  // beyond the fingertips
  EXPECT_EQ(points_in_closing_region(body, X_FrameHand, points), std::vector<std::int32_t>{0});
  EXPECT_EQ(points_in_collision(body, X_FrameHand, points), (std::vector<std::int32_t>{1, 2}));
}

}  // namespace
}  // namespace antipode
