// The octree built once per occupied leaf is octomap's point-by-point tree, node for node and
// value for value (octomap's own comparison of structure and values): for clouds with
// repeated points (leaves clamped at the maximum log-odds), runs of one leaf, leaves hit a
// few times, whole occupied blocks (pruned into their parents), points outside the key
// range and points that are not finite.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "points_octree.hpp"
#include "sphere_kernels.hpp"

namespace antipode::collision {
namespace {

void expect_same_tree(const std::vector<Eigen::Vector3f>& points, double resolution_m) {
  const auto fast = points_octree(points, resolution_m);
  const auto reference = points_octree_point_by_point(points, resolution_m);
  EXPECT_EQ(fast->size(), reference->size());
  EXPECT_EQ(fast->getNumLeafNodes(), reference->getNumLeafNodes());
  EXPECT_TRUE(*fast == *reference);
}

// A table top seen row by row (runs of one leaf), a pile of random points over it hit one to
// a dozen times each, and a solid cube filling whole blocks of leaves.
std::vector<Eigen::Vector3f> capture_like(std::uint64_t seed) {
  RandomStream random(seed);
  std::vector<Eigen::Vector3f> points;
  for (int row = 0; row < 120; ++row)
    for (int col = 0; col < 400; ++col)
      points.emplace_back(0.4f + 0.001f * float(col), -0.3f + 0.004f * float(row), -0.295f);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3f p(float(random.uniform(0.45, 0.75)), float(random.uniform(-0.35, -0.05)),
                            float(-0.29 + 0.1 * random.uniform()));
    const int repeats = 1 + int(random.uniform() * 12.0);
    for (int r = 0; r < repeats; ++r) points.push_back(p);
  }
  for (int x = 0; x < 16; ++x)
    for (int y = 0; y < 16; ++y)
      for (int z = 0; z < 16; ++z)
        points.emplace_back(0.8f + 0.005f * float(x), 0.1f + 0.005f * float(y),
                            0.005f * float(z) + 0.0025f);
  return points;
}

// The leaf keys are computed by a loop built for AVX2 and for the baseline instruction set:
// both, whichever this CPU has.
TEST(PointsOctree, SameTreeAsPointByPointInsertion) {
  const SimdLevel widest = simd_level();
  for (const SimdLevel level : {widest, SimdLevel::kBaseline}) {
    SCOPED_TRACE(to_string(set_simd_level(level)));
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(seed);
      const std::vector<Eigen::Vector3f> points = capture_like(seed);
      expect_same_tree(points, 0.01);
      expect_same_tree(points, 0.005);
    }
  }
  set_simd_level(widest);
}

// Points spread thinly over a large space (more blocks of leaves than the counts may take)
// are counted leaf by leaf: the same tree.
TEST(PointsOctree, SparseCloudsGiveTheSameTree) {
  RandomStream random(9);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 3000; ++i)
    points.emplace_back(float(random.uniform(-5.0, 5.0)), float(random.uniform(-5.0, 5.0)),
                        float(random.uniform(0.0, 3.0)));
  expect_same_tree(points, 0.01);
  expect_same_tree(points, 0.002);
}

TEST(PointsOctree, LeavesOutWhatOctomapLeavesOut) {
  std::vector<Eigen::Vector3f> points = capture_like(4);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  points.insert(points.begin() + 10, Eigen::Vector3f(nan, 0.0f, 0.0f));
  points.emplace_back(std::numeric_limits<float>::infinity(), 0.0f, 0.0f);
  points.emplace_back(1e6f, 0.0f, 0.0f);  // beyond the key range at 1 cm (about 327 m)
  points.emplace_back(0.0f, -std::numeric_limits<float>::infinity(), 0.0f);
  points.emplace_back(0.0f, nan, 0.0f);
  points.emplace_back(0.0f, 0.0f, nan);
  points.emplace_back(-327.68f, 0.0f, 0.0f);  // at the ends of the key range at 1 cm
  points.emplace_back(0.0f, 327.675f, 0.0f);
  points.emplace_back(0.0f, 0.0f, -327.69f);
  const SimdLevel widest = simd_level();
  for (const SimdLevel level : {widest, SimdLevel::kBaseline}) {
    SCOPED_TRACE(to_string(set_simd_level(level)));
    expect_same_tree(points, 0.01);
  }
  set_simd_level(widest);
  EXPECT_EQ(points_octree({}, 0.01)->size(), 0u);
}

}  // namespace
}  // namespace antipode::collision
