#include "grasp_balance.hpp"

#include "antipode/geometry/hand_body.hpp"

#include <cmath>

namespace antipode::selectors {

std::vector<Eigen::Vector3f> object_points(const Cloud& cloud,
                                           const std::optional<SupportPlane>& support,
                                           float above_m) {
  std::vector<Eigen::Vector3f> points;
  for (const auto& p : cloud.points_m)
    if (!support || support->distance(p) > above_m) points.push_back(p);
  return points;
}

std::optional<Eigen::Vector3d> centroid_near(const std::vector<Eigen::Vector3f>& points,
                                             const Eigen::Vector3d& centre, double radius_m) {
  const Eigen::Vector3f c = centre.cast<float>();
  const float r2 = float(radius_m * radius_m);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (const auto& p : points)
    if ((p - c).squaredNorm() <= r2) {
      sum += p.cast<double>();
      ++n;
    }
  if (n == 0) return std::nullopt;
  return Eigen::Vector3d(sum / double(n));
}

std::optional<Eigen::Vector3d> object_centroid_near(const Cloud& cloud, const SceneObject& object,
                                                    const Eigen::Vector3d& centre,
                                                    double radius_m) {
  std::vector<Eigen::Vector3f> points;
  points.reserve(object.points.size());
  for (const std::int32_t i : object.points) points.push_back(cloud.points_m[std::size_t(i)]);
  return centroid_near(points, centre, radius_m);
}

double torque_arm_m(const Hand& hand, const HandGeometry& geometry, const Eigen::Vector3d& centroid,
                    const Eigen::Vector3d& up) {
  return std::abs((centroid - grasp_centre(hand, geometry)).dot(up.cross(hand.closing())));
}

}  // namespace antipode::selectors
