#pragma once
// Toy hands for classifier tests: synthetic closing regions that are separable by their
// grasp images, a positive one holding two surfaces across the fingers, a negative one.

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/random.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode::testing {

/// Points in hand coordinates of a synthetic closing region: a positive example sees an
/// object's surface on both sides (two lines along the approach), a negative one a single
/// surface somewhere across it.
inline std::vector<Eigen::Vector3d> toy_points(bool positive, RandomStream& random) {
  const double start_m = random.uniform(0.0, 0.03);
  std::vector<double> lines_m;
  if (positive) {
    const double width_m = random.uniform(0.02, 0.05);
    const double centre_m = random.uniform(-0.01, 0.01);
    lines_m = {centre_m - width_m / 2, centre_m + width_m / 2};
  } else {
    lines_m = {random.uniform(-0.03, 0.03)};
  }
  std::vector<Eigen::Vector3d> points;
  for (const double y : lines_m) {
    for (double x = start_m; x < 0.06; x += 0.001) {
      points.emplace_back(x, y + random.uniform(-0.001, 0.001), 0.0);
    }
  }
  return points;
}

/// One toy hand per flag, each 1 m from the last and turned its own way, sharing one cloud.
inline HandSet toy_hand_set(const std::vector<bool>& positive, RandomStream& random) {
  auto cloud = std::make_shared<Cloud>();
  HandSet set;
  for (std::size_t i = 0; i < positive.size(); ++i) {
    Hand hand;
    hand.X_FrameHand = Eigen::Translation3d(0.0, 0.0, static_cast<double>(i)) *
                       Eigen::AngleAxisd(0.3 * static_cast<double>(i), Eigen::Vector3d::UnitX());
    hand.sample_index = static_cast<std::int32_t>(i);
    for (const Eigen::Vector3d& p : toy_points(positive[i], random)) {
      cloud->points_m.push_back((hand.X_FrameHand * p).cast<float>());
      hand.closing_points.push_back(static_cast<std::int32_t>(cloud->size() - 1));
    }
    set.hands.push_back(hand);
  }
  set.cloud = cloud;
  return set;
}

}  // namespace antipode::testing
