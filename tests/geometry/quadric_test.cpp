#include "antipode/geometry/quadric.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"

namespace antipode {
namespace {

std::vector<std::int32_t> all_indices(std::size_t n) {
  std::vector<std::int32_t> indices(n);
  for (std::size_t i = 0; i < n; ++i) indices[i] = static_cast<std::int32_t>(i);
  return indices;
}

// Points of a sphere cap around +z, radius r, centred at c.
std::vector<Eigen::Vector3f> sphere_cap(const Eigen::Vector3d& c, double r) {
  std::vector<Eigen::Vector3f> points;
  RandomStream random(5);
  for (int i = 0; i < 300; ++i) {
    const double theta = random.uniform(0.0, 0.6), phi = random.uniform(0.0, 2 * M_PI);
    const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                            std::cos(theta));
    points.push_back((c + r * n).cast<float>());
  }
  return points;
}

TEST(QuadricTest, SphereFitPassesThroughItsPointsWithRadialNormals) {
  const Eigen::Vector3d centre(0.1, -0.2, 0.6);
  const auto points = sphere_cap(centre, 0.03);
  const Eigen::Vector3d top = centre + Eigen::Vector3d(0, 0, 0.03);
  const auto quadric = fit_taubin_quadric(points, all_indices(points.size()), top, 0.02);
  ASSERT_TRUE(quadric.has_value());
  for (const auto& p : points) {
    const Eigen::Vector3d q = p.cast<double>();
    const Eigen::Vector3d g = quadric->gradient(q);
    EXPECT_NEAR(std::abs(quadric->value(q)) / g.norm(), 0.0, 1e-4);  // algebraic distance
    EXPECT_GT(std::abs(g.normalized().dot((q - centre).normalized())), 0.999);
  }
}

TEST(QuadricTest, CylinderNormalsAreRadial) {
  std::vector<Eigen::Vector3f> points;
  const double r = 0.02;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 15; ++j) {
      const double angle = -1.0 + 2.0 * i / 19.0;
      points.emplace_back(r * std::sin(angle), 0.004 * j - 0.03, 0.6 - r * std::cos(angle));
    }
  }
  const Eigen::Vector3d sample(0.0, 0.0, 0.6 - r);
  const auto quadric = fit_taubin_quadric(points, all_indices(points.size()), sample, 0.02);
  ASSERT_TRUE(quadric.has_value());
  const Eigen::Vector3d n = quadric->gradient(sample).normalized();
  EXPECT_GT(std::abs(n.z()), 0.9999);
}

TEST(QuadricTest, DegenerateInputsGiveNothing) {
  std::vector<Eigen::Vector3f> plane;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) plane.emplace_back(0.003f * i, 0.003f * j, 0.5f);
  }
  EXPECT_FALSE(fit_taubin_quadric(plane, all_indices(plane.size()), {0, 0, 0.5}, 0.02));
  const std::vector<Eigen::Vector3f> few(plane.begin(), plane.begin() + 8);
  EXPECT_FALSE(fit_taubin_quadric(few, all_indices(few.size()), {0, 0, 0.5}, 0.02));
}

}  // namespace
}  // namespace antipode
