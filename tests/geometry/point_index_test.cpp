#include "antipode/geometry/point_index.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"

namespace antipode {
namespace {

TEST(PointIndexTest, RadiusSearchMatchesBruteForce) {
  RandomStream random(3);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 5000; ++i) {
    points.emplace_back(random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2),
                        random.uniform(0.5, 0.7));
  }
  const PointIndex index(points);
  EXPECT_EQ(index.size(), points.size());
  std::vector<std::int32_t> found;
  for (int q = 0; q < 50; ++q) {
    const Eigen::Vector3f centre = points[static_cast<std::size_t>(q * 97)];
    const float radius = 0.01f + 0.002f * q;
    index.radius_search(centre, radius, found);
    std::vector<std::int32_t> expected;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if ((points[i] - centre).squaredNorm() <= radius * radius) {
        expected.push_back(static_cast<std::int32_t>(i));
      }
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "query " << q;
  }
}

TEST(PointIndexTest, EmptyIndexFindsNothing) {
  const std::vector<Eigen::Vector3f> none;
  const PointIndex index(none);
  std::vector<std::int32_t> found = {1, 2};
  index.radius_search(Eigen::Vector3f::Zero(), 1.0f, found);
  EXPECT_TRUE(found.empty());
}

}  // namespace
}  // namespace antipode
