// One line describing a scene layout (scene_layout.hpp): the support, then each object,
// sized along the cloud's axes or, given the points, along the support.
#include <algorithm>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include "antipode/geometry/scene_layout.hpp"
#include "convex_hull.hpp"

namespace antipode {
namespace {

std::string support_text(const SupportPlane& support, std::size_t objects) {
  char line[200];
  std::snprintf(line, sizeof line,
                "support plane %.3f x + %.3f y + %.3f z + %.3f = 0 (%zu points), %zu object%s",
                double(support.normal.x()), double(support.normal.y()), double(support.normal.z()),
                double(support.offset), support.inliers, objects, objects == 1 ? "" : "s");
  return line;
}

// The sides (cm, longer first) of the smallest rectangle around the object's footprint on
// the plane: one of its sides lies along an edge of the footprint's convex hull.
Eigen::Vector2d footprint_cm(const SceneObject& object, const SupportPlane& support,
                             const std::vector<Eigen::Vector3f>& points) {
  const Eigen::Vector3f n = support.normal;
  const Eigen::Vector3f e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  std::vector<Eigen::Vector2f> flat;
  for (const std::int32_t i : object.points) {
    if (i < 0 || std::size_t(i) >= points.size()) continue;  // not this cloud's
    flat.emplace_back(e1.dot(points[std::size_t(i)]), e2.dot(points[std::size_t(i)]));
  }
  const std::vector<Eigen::Vector2f> hull = geometry::convex_hull(std::move(flat));
  if (hull.size() < 3) return Eigen::Vector2d::Zero();
  Eigen::Vector2d best(1e30, 1e30);
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const Eigen::Vector2f edge = hull[(k + 1) % hull.size()] - hull[k];
    if (edge.norm() <= 0.0f) continue;
    const Eigen::Vector2f u = edge.normalized(), v(-u.y(), u.x());
    float lo_u = 1e30f, hi_u = -1e30f, lo_v = 1e30f, hi_v = -1e30f;
    for (const Eigen::Vector2f& q : hull) {
      lo_u = std::min(lo_u, u.dot(q)), hi_u = std::max(hi_u, u.dot(q));
      lo_v = std::min(lo_v, v.dot(q)), hi_v = std::max(hi_v, v.dot(q));
    }
    const Eigen::Vector2d sides(double(hi_u - lo_u), double(hi_v - lo_v));
    if (sides.prod() < best.prod()) best = sides;
  }
  return Eigen::Vector2d(best.maxCoeff(), best.minCoeff()) * 100.0;
}

}  // namespace

std::string SceneLayout::summary() const { return describe_scene(support, objects); }

std::string describe_scene(const std::optional<SupportPlane>& support,
                           const std::vector<SceneObject>& objects) {
  if (!support) return "no support surface: the whole cloud is used";
  std::string text = support_text(*support, objects.size());
  char line[200];
  for (const SceneObject& o : objects) {
    const Eigen::Vector3f size = (o.max_m - o.min_m) * 100.0f;
    std::snprintf(line, sizeof line,
                  "%s #%d: %zu points, %.1f x %.1f x %.1f cm at (%.3f, %.3f, %.3f)",
                  o.id == 0 ? ":" : ";", o.id, o.points.size(), double(size.x()), double(size.y()),
                  double(size.z()), double(o.centroid_m.x()), double(o.centroid_m.y()),
                  double(o.centroid_m.z()));
    text += line;
  }
  return text;
}

std::string describe_scene(const std::optional<SupportPlane>& support,
                           const std::vector<SceneObject>& objects,
                           const std::vector<Eigen::Vector3f>& points) {
  if (!support) return "no support surface: the whole cloud is used";
  std::string text = support_text(*support, objects.size());
  char line[200];
  for (const SceneObject& o : objects) {
    const Eigen::Vector2d footprint = footprint_cm(o, *support, points);
    std::snprintf(line, sizeof line,
                  "%s #%d: %zu points, %.1f x %.1f cm on the support, %.1f cm tall at (%.3f, "
                  "%.3f, %.3f)",
                  o.id == 0 ? ":" : ";", o.id, o.points.size(), footprint.x(), footprint.y(),
                  double(o.height_m) * 100.0, double(o.centroid_m.x()), double(o.centroid_m.y()),
                  double(o.centroid_m.z()));
    text += line;
  }
  return text;
}

}  // namespace antipode
