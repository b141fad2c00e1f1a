// SlabGrid is internal to the geometry area (framework/src/geometry); tested here against
// brute force because the hand search's correctness rests on it.
#include "slab_grid.hpp"

#include <algorithm>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "antipode/core/random.hpp"

namespace antipode::geometry {
namespace {

TEST(SlabGridTest, QueryMatchesBruteForce) {
  RandomStream random(8);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 20000; ++i) {
    points.emplace_back(random.uniform(-0.3, 0.3), random.uniform(-0.1, 0.2),
                        random.uniform(0.5, 0.9));
  }
  const SlabGrid grid(points, 0.02f);
  std::vector<std::int32_t> found;
  for (int q = 0; q < 40; ++q) {
    const Eigen::Vector3f centre = points[static_cast<std::size_t>(q * 211)];
    const Eigen::Vector3f axis =
        Eigen::Vector3f(random.normal(), random.normal(), random.normal()).normalized();
    grid.query(centre, axis, 0.01f, 0.1f, found);
    std::vector<std::int32_t> expected;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3f d = points[i] - centre;
      if (std::abs(d.dot(axis)) <= 0.01f && d.norm() <= 0.1f) {
        expected.push_back(static_cast<std::int32_t>(i));
      }
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "query " << q;
  }
}

TEST(SlabGridTest, AxisAlignedSlabsAndEmptyGrids) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 50; ++i) points.emplace_back(0.01f * i, 0.0f, 0.001f * (i % 5));
  const SlabGrid grid(points, 0.02f);
  std::vector<std::int32_t> found;
  grid.query(points[10], Eigen::Vector3f::UnitX(), 0.015f, 1.0f, found);
  EXPECT_EQ(found.size(), 3u);
  const std::vector<Eigen::Vector3f> none;
  SlabGrid(none, 0.02f).query(Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitZ(), 1, 1, found);
  EXPECT_TRUE(found.empty());
}

}  // namespace
}  // namespace antipode::geometry
