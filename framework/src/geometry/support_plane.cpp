// RANSAC for the support plane, then a least-squares refit to its inliers.
#include "antipode/geometry/support_plane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "plane_facing.hpp"
#include "plane_fit.hpp"

namespace antipode {
namespace {

// Points used to score hypotheses: every k-th point, at most this many.
constexpr std::size_t kMaxScoringPoints = 4096;

struct Count {
  std::size_t inliers = 0;
  std::size_t below = 0;
  std::size_t above = 0;
};

Count count(const std::vector<Eigen::Vector3f>& points, const SupportPlane& plane,
            float distance_m) {
  Count c;
  for (const auto& p : points) {
    const float d = plane.distance(p);
    c.inliers += static_cast<std::size_t>(std::fabs(d) <= distance_m);
    c.below += static_cast<std::size_t>(d < -distance_m);
    c.above += static_cast<std::size_t>(d > distance_m);
  }
  return c;
}

// Orients `plane` so that `sensor` is on its positive side; false when the sensor is on the
// plane itself (within `distance_m`), which leaves no side to call free.
bool orient(SupportPlane& plane, const Eigen::Vector3f& sensor, float distance_m) {
  const float side = plane.distance(sensor);
  if (!(std::fabs(side) > distance_m)) return false;
  if (side < 0.0f) plane.normal = -plane.normal, plane.offset = -plane.offset;
  return true;
}

bool admissible(const Count& c, std::size_t total, const SupportPlaneOptions& o) {
  return static_cast<double>(c.below) <= o.max_below_fraction * static_cast<double>(total);
}

// The least-squares plane through the inliers of `plane`; `extent` receives the two
// in-plane directions of the inliers' spread.
bool refit(const std::vector<Eigen::Vector3f>& points, SupportPlane& plane, float distance_m,
           Eigen::Matrix<float, 3, 2>& extent) {
  std::vector<std::int32_t> inliers;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::fabs(plane.distance(points[i])) <= distance_m)
      inliers.push_back(static_cast<std::int32_t>(i));
  }
  return geometry::refit_plane(points, inliers, plane, extent);
}

// The fraction of the points above the plane whose foot lies within the rectangle (aligned
// with `extent`) that bounds the plane's inliers: objects standing on a support have their
// footprint on it; the rest of a can seen past a plane tangent to it does not.
double supported_fraction(const std::vector<Eigen::Vector3f>& points, const SupportPlane& plane,
                          float distance_m, const Eigen::Matrix<float, 3, 2>& extent) {
  Eigen::Vector2f lo = Eigen::Vector2f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector2f hi = -lo;
  for (const auto& p : points) {
    if (std::fabs(plane.distance(p)) > distance_m) continue;
    const Eigen::Vector2f q = extent.transpose() * p;
    lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  std::size_t above = 0, supported = 0;
  for (const auto& p : points) {
    if (!(plane.distance(p) > distance_m)) continue;
    ++above;
    const Eigen::Vector2f q = extent.transpose() * p;
    supported += static_cast<std::size_t>((q.array() >= lo.array()).all() &&
                                          (q.array() <= hi.array()).all());
  }
  return above == 0 ? 1.0 : static_cast<double>(supported) / static_cast<double>(above);
}

}  // namespace

std::optional<SupportPlane> find_support_plane(const Cloud& cloud,
                                               const Eigen::Vector3f& toward_sensor,
                                               const SupportPlaneOptions& options,
                                               RandomStream random) {
  const std::vector<Eigen::Vector3f>& points = cloud.points_m;
  const std::size_t total = points.size();
  if (total < std::max<std::size_t>(3, options.min_inliers)) return std::nullopt;
  const std::size_t stride = (total + kMaxScoringPoints - 1) / kMaxScoringPoints;
  std::vector<Eigen::Vector3f> scoring;
  scoring.reserve(total / stride + 1);
  for (std::size_t i = 0; i < total; i += stride) scoring.push_back(points[i]);

  std::optional<SupportPlane> best;
  std::size_t best_inliers = 0;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    const Eigen::Vector3f& a = points[random.below(total)];
    const Eigen::Vector3f& b = points[random.below(total)];
    const Eigen::Vector3f& c = points[random.below(total)];
    const Eigen::Vector3f cross = (b - a).cross(c - a);
    // Three points closer than about a centimetre to a line say little about a plane.
    if (!(cross.norm() > 1e-4f)) continue;
    SupportPlane plane;
    plane.normal = cross.normalized();
    plane.offset = -plane.normal.dot(a);
    if (!orient(plane, toward_sensor, options.distance_m)) continue;
    const Count c_sub = count(scoring, plane, options.distance_m);
    if (c_sub.inliers <= best_inliers || !admissible(c_sub, scoring.size(), options)) continue;
    best = plane;
    best_inliers = c_sub.inliers;
  }
  if (!best) return std::nullopt;
  SupportPlane plane = *best;
  Eigen::Matrix<float, 3, 2> extent;
  if (!refit(points, plane, options.distance_m, extent) ||
      !orient(plane, toward_sensor, options.distance_m)) {
    return std::nullopt;
  }
  const Count c = count(points, plane, options.distance_m);
  if (c.inliers < options.min_inliers ||
      static_cast<double>(c.inliers) < options.min_inlier_fraction * static_cast<double>(total) ||
      !admissible(c, total, options) ||
      static_cast<double>(c.above) <
          std::max(1.0, options.min_above_fraction * static_cast<double>(total)) ||
      supported_fraction(points, plane, options.distance_m, extent) <
          options.min_supported_fraction ||
      geometry::facing_fraction(scoring, plane, options.distance_m) < options.min_facing_fraction) {
    return std::nullopt;
  }
  plane.inliers = c.inliers;
  return plane;
}

}  // namespace antipode
