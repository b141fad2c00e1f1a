#include "plane_facing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include <Eigen/Eigenvalues>

namespace antipode::geometry {
namespace {

constexpr std::size_t kFacingProbes = 128;
constexpr float kFacingRadius_m = 0.015f;
constexpr float kFacingCosine = 0.9f;

// Whether the surface around `centre` (the neighbours' PCA normal) faces along `normal`;
// nullopt with too few neighbours to tell.
std::optional<bool> faces(const Eigen::Vector3f& centre, const std::vector<Eigen::Vector3f>& points,
                          const std::vector<std::int32_t>* neighbours,
                          const Eigen::Vector3f& normal) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  std::size_t n = 0;
  const auto add = [&](const Eigen::Vector3f& p) {
    if ((p - centre).squaredNorm() > kFacingRadius_m * kFacingRadius_m) return;
    const Eigen::Vector3d d = (p - centre).cast<double>();
    sum += d, moments += d * d.transpose(), ++n;
  };
  if (neighbours != nullptr) {
    for (const std::int32_t i : *neighbours) add(points[std::size_t(i)]);
  } else {
    for (const auto& p : points) add(p);
  }
  if (n < 6) return std::nullopt;
  const Eigen::Vector3d mean = sum / static_cast<double>(n);
  const Eigen::Matrix3d covariance = moments / static_cast<double>(n) - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  return std::fabs(solver.eigenvectors().col(0).cast<float>().dot(normal)) >= kFacingCosine;
}

double fraction(std::size_t facing, std::size_t probes) {
  return probes == 0 ? 0.0 : static_cast<double>(facing) / static_cast<double>(probes);
}

}  // namespace

double facing_fraction(const std::vector<Eigen::Vector3f>& points, const SupportPlane& plane,
                       float distance_m) {
  std::vector<std::size_t> inliers;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::fabs(plane.distance(points[i])) <= distance_m) inliers.push_back(i);
  }
  const std::size_t step = std::max<std::size_t>(1, inliers.size() / kFacingProbes);
  std::size_t probes = 0, facing = 0;
  for (std::size_t k = 0; k < inliers.size(); k += step) {
    const std::optional<bool> f = faces(points[inliers[k]], points, nullptr, plane.normal);
    probes += f.has_value(), facing += f.value_or(false);
  }
  return fraction(facing, probes);
}

double facing_fraction(const std::vector<Eigen::Vector3f>& points, const PointIndex& index,
                       const std::vector<std::int32_t>& inliers, const SupportPlane& plane) {
  const std::size_t step = std::max<std::size_t>(1, inliers.size() / kFacingProbes);
  std::vector<std::int32_t> near;
  std::size_t probes = 0, facing = 0;
  for (std::size_t k = 0; k < inliers.size(); k += step) {
    const Eigen::Vector3f& centre = points[std::size_t(inliers[k])];
    index.radius_search(centre, kFacingRadius_m, near);
    const std::optional<bool> f = faces(centre, points, &near, plane.normal);
    probes += f.has_value(), facing += f.value_or(false);
  }
  return fraction(facing, probes);
}

}  // namespace antipode::geometry
