// Euclidean clustering (framework/src/geometry/euclidean_clusters.hpp): the same clusters as
// region growing with the point index's ball queries, on clouds where many pairs lie near the
// tolerance.
#include "euclidean_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/point_index.hpp"

namespace antipode::geometry {
namespace {

// Region growing with a ball query per member: the definition the grid must reproduce.
std::vector<std::vector<std::int32_t>> by_ball_queries(const std::vector<Eigen::Vector3f>& points,
                                                       const std::vector<std::int32_t>& members,
                                                       float tolerance_m) {
  std::vector<std::int32_t> sorted = members;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Eigen::Vector3f> subset;
  for (const std::int32_t i : sorted) subset.push_back(points[std::size_t(i)]);
  const PointIndex index(subset);
  std::vector<char> taken(subset.size(), 0);
  std::vector<std::int32_t> near;
  std::vector<std::vector<std::int32_t>> clusters;
  for (std::size_t seed = 0; seed < subset.size(); ++seed) {
    if (taken[seed]) continue;
    std::vector<std::int32_t> cluster{std::int32_t(seed)};
    taken[seed] = 1;
    for (std::size_t next = 0; next < cluster.size(); ++next) {
      index.radius_search(subset[std::size_t(cluster[next])], tolerance_m, near);
      for (const std::int32_t j : near)
        if (!taken[std::size_t(j)]) taken[std::size_t(j)] = 1, cluster.push_back(j);
    }
    for (std::int32_t& j : cluster) j = sorted[std::size_t(j)];
    std::sort(cluster.begin(), cluster.end());
    clusters.push_back(cluster);
  }
  return clusters;
}

// Points on a lattice of spacing `spacing_m` (plus a small jitter): with the tolerance near
// the spacing, whether neighbours join is decided in the last bits of their distance.
std::vector<Eigen::Vector3f> lattice(int n, float spacing_m, float jitter_m, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> jitter(-jitter_m, jitter_m);
  std::bernoulli_distribution keep(0.6);
  std::vector<Eigen::Vector3f> points;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y)
      for (int z = 0; z < n / 4; ++z)
        if (keep(random))
          points.emplace_back(0.37f + x * spacing_m + jitter(random),
                              -0.21f + y * spacing_m + jitter(random),
                              z * spacing_m + jitter(random));
  return points;
}

TEST(EuclideanClusters, TheSameClustersAsRegionGrowingWithBallQueries) {
  for (unsigned seed = 0; seed < 6; ++seed) {
    for (const float jitter_m : {0.0f, 1e-6f, 0.002f}) {
      const std::vector<Eigen::Vector3f> points = lattice(24, 0.01f, jitter_m, seed);
      std::vector<std::int32_t> members;
      for (std::size_t i = 0; i < points.size(); i += 1 + seed % 2)
        members.push_back(std::int32_t(i));
      std::reverse(members.begin(), members.end());  // any order in, sorted out
      for (const float tolerance_m : {0.01f, 0.0100001f, 0.012f, 0.02f, 0.003f}) {
        SCOPED_TRACE(::testing::Message() << "seed " << seed << ", jitter " << jitter_m
                                          << ", tolerance " << tolerance_m);
        const auto want = by_ball_queries(points, members, tolerance_m);
        const auto got = euclidean_clusters(points, members, tolerance_m);
        ASSERT_EQ(got, want);
      }
    }
  }
}

TEST(EuclideanClusters, TheSameClustersOnSparseCloudsOfManySmallClusters) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> within(-0.05f, 0.05f);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Vector3f> points(400);
    for (auto& p : points) p = {0.6f + within(random), -0.2f + within(random), within(random)};
    std::vector<std::int32_t> all(points.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = std::int32_t(i);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    const auto want = by_ball_queries(points, all, 0.01f);
    ASSERT_GT(want.size(), 50u);  // many clusters: pairs near the tolerance decide them
    ASSERT_EQ(euclidean_clusters(points, all, 0.01f), want);
  }
}

TEST(EuclideanClusters, ChainsJoinAndGapsSplit) {
  // Two chains of points 9 mm apart, 3 cm between the chains: two clusters at 1 cm, one at 4 cm.
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 10; ++i) points.emplace_back(i * 0.009f, 0.0f, 0.0f);
  for (int i = 0; i < 10; ++i) points.emplace_back(0.081f + 0.03f + i * 0.009f, 0.0f, 0.0f);
  std::vector<std::int32_t> all(points.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = std::int32_t(i);
  EXPECT_EQ(euclidean_clusters(points, all, 0.01f).size(), 2u);
  EXPECT_EQ(euclidean_clusters(points, all, 0.04f).size(), 1u);
  EXPECT_EQ(euclidean_clusters(points, all, 0.005f).size(), 20u);
  EXPECT_TRUE(euclidean_clusters(points, {}, 0.01f).empty());
}

TEST(EuclideanClusters, ToleranceOutsideItsRangeIsAnError) {
  const std::vector<Eigen::Vector3f> points = {{0, 0, 0}};
  for (const float tolerance_m :
       {0.0f, -0.01f, 1e-20f, 1e20f, std::numeric_limits<float>::quiet_NaN()}) {
    SCOPED_TRACE(tolerance_m);
    EXPECT_THROW(euclidean_clusters(points, {0}, tolerance_m), Error);
  }
}

TEST(EuclideanClusters, PointsThatAreNotFiniteStandAlone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<Eigen::Vector3f> points = {{0, 0, 0},   {nan, 0, 0}, {0.001f, 0, 0},
                                               {inf, 0, 0}, {inf, 0, 0}, {1e30f, 0, 0}};
  const std::vector<std::vector<std::int32_t>> want = {{0, 2}, {1}, {3}, {4}, {5}};
  EXPECT_EQ(euclidean_clusters(points, {0, 1, 2, 3, 4, 5}, 0.01f), want);
}

}  // namespace
}  // namespace antipode::geometry
