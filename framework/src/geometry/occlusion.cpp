#include "antipode/geometry/occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace antipode {
namespace {

// Points whose depth along the view's mean direction is below this fraction of their range
// (about 78 degrees off axis) are not projected: the tangent-plane image would stretch.
constexpr float kMinAxialFraction = 0.2f;
// Image size limit per axis; coarser pixels are used beyond it.
constexpr int kMaxPixels = 2048;
// Largest splat radius in pixels.
constexpr int kMaxSplat = 4;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

}  // namespace

struct OcclusionMap::View {
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();
  Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();  // rows: image x, image y, axis
  float pixel = 1.0f;                                      // tangent-plane units per pixel
  float min_u = 0.0f, min_v = 0.0f;
  int width = 0, height = 0;
  std::vector<float> range;  // nearest range per pixel, row-major

  // Image coordinates of p (false when p is too far off axis or behind the sensor).
  bool project(const Eigen::Vector3f& p, float& u, float& v, float& depth) const {
    const Eigen::Vector3f d = rotation * (p - origin);
    depth = d.z();
    if (!(depth > kMinAxialFraction * d.norm())) return false;
    u = (d.x() / depth - min_u) / pixel;
    v = (d.y() / depth - min_v) / pixel;
    return true;
  }

  bool hidden(const Eigen::Vector3f& p, float margin) const {
    float u = 0, v = 0, depth = 0;
    if (!project(p, u, v, depth)) return false;
    const int col = static_cast<int>(std::floor(u)), row = static_cast<int>(std::floor(v));
    if (col < 0 || row < 0 || col >= width || row >= height) return false;
    return range[static_cast<std::size_t>(row) * width + col] < (p - origin).norm() - margin;
  }

  // Builds the image of view `v` of `cloud`; false when the view has no usable point.
  bool build(const Cloud& cloud, std::size_t v, float point_radius) {
    origin = cloud.view_origins_m[v];
    std::vector<Eigen::Vector3f> points;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const bool seen = cloud.view_masks.empty() ? v == 0 : ((cloud.view_masks[i] >> v) & 1u);
      if (seen && cloud.points_m[i] != origin) points.push_back(cloud.points_m[i]);
    }
    return set_axis(points) && set_bounds(points, point_radius) &&
           (splat(points, point_radius), true);
  }

  // The image axis: the mean direction from the origin to the points.
  bool set_axis(const std::vector<Eigen::Vector3f>& points) {
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();
    for (const auto& p : points) mean += (p - origin).normalized();
    if (points.empty() || mean.norm() < 1e-3f * points.size()) return false;
    const Eigen::Vector3f axis = mean.normalized();
    const Eigen::Vector3f x = axis.unitOrthogonal();
    rotation.row(0) = x;
    rotation.row(1) = axis.cross(x);
    rotation.row(2) = axis;
    return true;
  }

  // Pixel size (a point's radius at the mean range, coarser for very wide views) and extent.
  bool set_bounds(const std::vector<Eigen::Vector3f>& points, float point_radius) {
    pixel = 1.0f, min_u = 0.0f, min_v = 0.0f;
    float lo_u = kInfinity, lo_v = kInfinity, hi_u = -kInfinity, hi_v = -kInfinity;
    double range_sum = 0.0;
    for (const auto& p : points) {
      float u, w, depth;
      if (!project(p, u, w, depth)) continue;
      lo_u = std::min(lo_u, u), hi_u = std::max(hi_u, u);
      lo_v = std::min(lo_v, w), hi_v = std::max(hi_v, w);
      range_sum += (p - origin).norm();
    }
    if (!(hi_u >= lo_u)) return false;
    const float mean_range = static_cast<float>(range_sum / points.size());
    pixel = std::max({std::max(point_radius, 1e-4f) / mean_range, (hi_u - lo_u) / (kMaxPixels - 1),
                      (hi_v - lo_v) / (kMaxPixels - 1)});
    min_u = lo_u - pixel * kMaxSplat;
    min_v = lo_v - pixel * kMaxSplat;
    width = static_cast<int>((hi_u - lo_u) / pixel) + 2 * kMaxSplat + 2;
    height = static_cast<int>((hi_v - lo_v) / pixel) + 2 * kMaxSplat + 2;
    range.assign(static_cast<std::size_t>(width) * height, kInfinity);
    return true;
  }

  // Every point covers the pixels within its radius with its range.
  void splat(const std::vector<Eigen::Vector3f>& points, float point_radius) {
    for (const auto& p : points) {
      float u, w, depth;
      if (!project(p, u, w, depth)) continue;
      const float r = (p - origin).norm();
      const float radius = point_radius / (depth * pixel);
      const int k = std::min(kMaxSplat, static_cast<int>(std::ceil(radius)));
      const float reach = (radius + 0.5f) * (radius + 0.5f);
      const int col = static_cast<int>(std::floor(u)), row = static_cast<int>(std::floor(w));
      for (int dr = -k; dr <= k; ++dr) {
        for (int dc = -k; dc <= k; ++dc) {
          if (static_cast<float>(dr * dr + dc * dc) > reach) continue;
          float& cell = range[static_cast<std::size_t>(row + dr) * width + (col + dc)];
          cell = std::min(cell, r);
        }
      }
    }
  }
};

OcclusionMap::OcclusionMap(const Cloud& cloud, float point_radius_m) {
  for (std::size_t v = 0; v < cloud.view_origins_m.size() && v < 32; ++v) {
    auto view = std::make_unique<View>();
    if (view->build(cloud, v, point_radius_m)) views_.push_back(std::move(view));
  }
}

OcclusionMap::~OcclusionMap() = default;
OcclusionMap::OcclusionMap(OcclusionMap&&) noexcept = default;
OcclusionMap& OcclusionMap::operator=(OcclusionMap&&) noexcept = default;

bool OcclusionMap::hidden(const Eigen::Vector3f& p, float margin_m) const {
  if (views_.empty()) return false;
  for (const auto& view : views_) {
    if (!view->hidden(p, margin_m)) return false;
  }
  return true;
}

}  // namespace antipode
