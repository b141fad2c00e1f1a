// Per view: find the support plane among the view's points, compare the origin's distance
// to it with the distance to the known support, and scale the view's points about the
// origin by their ratio (a scaling about the origin keeps the plane's orientation and
// scales its distance from the origin).
#include "antipode/geometry/depth_scale.hpp"

#include <cmath>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode {
namespace {

// The points of view `v` alone (a point seen in several views is left to none: its depth
// came from one of them, and which one is not recorded).
std::vector<std::size_t> view_points(const Cloud& cloud, std::size_t v) {
  std::vector<std::size_t> indices;
  const std::uint32_t bit = 1u << v;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.view_masks.empty() ? v == 0 : cloud.view_masks[i] == bit) indices.push_back(i);
  return indices;
}

ViewScale correct_view(Cloud& cloud, std::size_t v, const DepthScaleOptions& options,
                       const RandomStream& random) {
  ViewScale result;
  const std::vector<std::size_t> indices = view_points(cloud, v);
  result.points = indices.size();
  Cloud view;
  view.frame = cloud.frame;
  view.view_origins_m = {cloud.view_origins_m[v]};
  for (std::size_t i : indices) view.points_m.push_back(cloud.points_m[i]);
  view.view_masks.assign(view.size(), 1u);
  const Eigen::Vector3f origin = cloud.view_origins_m[v];
  const auto plane = find_support_plane(view, origin, SupportPlaneOptions{}, random.derive(v));
  if (!plane) return result;
  if (plane->normal.z() < std::cos(options.max_tilt_deg * M_PI / 180.0)) return result;
  // The plane's height under the origin, and the support's: the factor is their ratio of
  // distances from the origin.
  const double seen_distance = plane->distance(origin) / plane->normal.z();
  result.seen_height_m = origin.z() - seen_distance;
  const double true_distance = origin.z() - options.support_height_m;
  if (!(seen_distance > 0.0 && true_distance > 0.0)) return result;
  result.factor = true_distance / seen_distance;
  if (!(std::abs(result.factor - 1.0) <= options.max_correction)) return result;
  for (std::size_t i : indices)
    cloud.points_m[i] = origin + float(result.factor) * (cloud.points_m[i] - origin);
  result.corrected = true;
  return result;
}

}  // namespace

std::vector<ViewScale> correct_depth_scale(Cloud& cloud, const DepthScaleOptions& options,
                                           const RandomStream& random) {
  if (cloud.view_origins_m.empty())
    throw Error("depth scale: the cloud has no view origins to scale its views about");
  if (!(options.max_correction > 0.0 && options.max_correction < 1.0))
    throw Error("depth scale: max_correction must be in (0, 1)");
  std::vector<ViewScale> views;
  for (std::size_t v = 0; v < cloud.view_origins_m.size(); ++v)
    views.push_back(correct_view(cloud, v, options, random));
  return views;
}

}  // namespace antipode
