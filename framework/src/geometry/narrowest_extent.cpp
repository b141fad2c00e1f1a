// The narrowest horizontal extent (the contract is in narrowest_extent.hpp): the points'
// projection on the xy plane, its convex hull, and for each hull edge the farthest hull
// vertex from the edge's line - the least of those distances is the width.
#include "antipode/geometry/narrowest_extent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "convex_hull.hpp"

namespace antipode {

double narrowest_horizontal_extent_m(const std::vector<Eigen::Vector3d>& points_m) {
  if (points_m.empty()) return 0.0;
  // Relative to the first point: the projection in single precision keeps its micrometres
  // however far the object lies from the frame's origin.
  const Eigen::Vector2d origin = points_m.front().head<2>();
  std::vector<Eigen::Vector2f> flat;
  flat.reserve(points_m.size());
  for (const Eigen::Vector3d& p : points_m) flat.push_back((p.head<2>() - origin).cast<float>());
  const std::vector<Eigen::Vector2f> hull = geometry::convex_hull(std::move(flat));
  if (hull.size() < 3) return 0.0;
  double narrowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d a = hull[i].cast<double>();
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()].cast<double>() - a;
    const Eigen::Vector2d normal = Eigen::Vector2d(-edge.y(), edge.x()).normalized();
    double farthest = 0.0;
    for (const Eigen::Vector2f& q : hull)
      farthest = std::max(farthest, std::abs(normal.dot(q.cast<double>() - a)));
    narrowest = std::min(narrowest, farthest);
  }
  return narrowest;
}

}  // namespace antipode
