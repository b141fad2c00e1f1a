#include "hand_checks.hpp"

#include <gtest/gtest.h>

#include "antipode/geometry/hand_body.hpp"

namespace antipode::testing {
namespace {

// Tolerance for points on the closing region's boundary (the search works in float).
constexpr double kTolerance = 1e-5;

void expect_closing_points_inside(const Cloud& cloud, const Hand& hand, const HandBody& body,
                                  std::size_t h) {
  const Eigen::Isometry3d X_HandFrame = hand.X_FrameHand.inverse();
  for (const std::int32_t i : hand.closing_points) {
    ASSERT_GE(i, 0);
    ASSERT_LT(static_cast<std::size_t>(i), cloud.size());
    const Eigen::Vector3d p =
        X_HandFrame * cloud.points_m[static_cast<std::size_t>(i)].cast<double>();
    EXPECT_TRUE(p.x() >= -kTolerance && p.x() <= body.depth_m + kTolerance &&
                std::abs(p.y()) < body.half_aperture_m + kTolerance &&
                std::abs(p.z()) <= body.half_height_m + kTolerance)
        << "hand " << h << " closing point " << i << " at " << p.transpose();
  }
}

void expect_stats_add_up(const HandSearchResult& result) {
  const HandSearchStats& s = result.stats;
  EXPECT_EQ(s.poses,
            s.acceptable + s.below_support + s.hidden + s.in_collision + s.empty + s.too_shallow);
  EXPECT_EQ(s.samples,
            s.frames_quadric + s.frames_planar + s.skipped_too_few + s.skipped_collinear);
  EXPECT_EQ(s.samples, result.sample_points.size());
  EXPECT_EQ(s.hands, result.hands.size());
  EXPECT_LE(s.hands, s.acceptable);
}

}  // namespace

void expect_valid_hands(const Cloud& cloud, const HandSearchResult& result,
                        const HandSearchParameters& parameters) {
  const HandBody body = make_hand_body(parameters.hand);
  for (std::size_t h = 0; h < result.hands.size(); ++h) {
    const Hand& hand = result.hands[h];
    const Eigen::Matrix3d R = hand.X_FrameHand.linear();
    EXPECT_TRUE(R.isUnitary(1e-5)) << "hand " << h;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-5) << "hand " << h;
    EXPECT_EQ(hand.frame, cloud.frame);
    ASSERT_GE(hand.sample_index, 0);
    ASSERT_LT(static_cast<std::size_t>(hand.sample_index), cloud.size());
    EXPECT_FALSE(hand.closing_points.empty()) << "hand " << h;
    EXPECT_GE(hand.width_m, 0.0);
    EXPECT_LT(hand.width_m, parameters.hand.max_aperture_m);
    const double min_bite =
        result.support_plane ? parameters.min_bite_at_support_m : parameters.min_bite_m;
    EXPECT_GE(hand.score, min_bite - 1e-6);
    EXPECT_EQ(hand.rejection, Rejection::kNone);
    const auto colliding = points_in_collision(body, hand.X_FrameHand, cloud.points_m);
    EXPECT_TRUE(colliding.empty()) << "hand " << h << " collides with " << colliding.size()
                                   << " points, e.g. " << colliding.front();
    expect_closing_points_inside(cloud, hand, body, h);
  }
  expect_stats_add_up(result);
}

bool same_hands(const HandSearchResult& a, const HandSearchResult& b) {
  if (a.hands.size() != b.hands.size() || a.sample_points != b.sample_points) return false;
  for (std::size_t i = 0; i < a.hands.size(); ++i) {
    const Hand& x = a.hands[i];
    const Hand& y = b.hands[i];
    if (x.X_FrameHand.matrix() != y.X_FrameHand.matrix() || x.closing_points != y.closing_points ||
        x.width_m != y.width_m || x.sample_index != y.sample_index || x.score != y.score) {
      return false;
    }
  }
  return true;
}

}  // namespace antipode::testing
