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

namespace {

// The centroid of the points point(k), k < count, within `radius_m` of `centre`.
template <class PointAt>
std::optional<Eigen::Vector3d> centroid_within(std::size_t count, PointAt point,
                                               const Eigen::Vector3d& centre, double radius_m) {
  const Eigen::Vector3f c = centre.cast<float>();
  const float r2 = float(radius_m * radius_m);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const Eigen::Vector3f& p = point(k);
    if ((p - c).squaredNorm() <= r2) {
      sum += p.cast<double>();
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return Eigen::Vector3d(sum / double(n));
}

}  // namespace

std::optional<Eigen::Vector3d> centroid_near(const std::vector<Eigen::Vector3f>& points,
                                             const Eigen::Vector3d& centre, double radius_m) {
  return centroid_within(
      points.size(), [&](std::size_t k) -> const Eigen::Vector3f& { return points[k]; }, centre,
      radius_m);
}

std::optional<Eigen::Vector3d> object_centroid_near(const Cloud& cloud, const SceneObject& object,
                                                    const Eigen::Vector3d& centre,
                                                    double radius_m) {
  return centroid_within(
      object.points.size(),
      [&](std::size_t k) -> const Eigen::Vector3f& {
        return cloud.points_m[std::size_t(object.points[k])];
      },
      centre, radius_m);
}

double torque_arm_m(const Hand& hand, const HandGeometry& geometry, const Eigen::Vector3d& centroid,
                    const Eigen::Vector3d& up) {
  return std::abs((centroid - grasp_centre(hand, geometry)).dot(up.cross(hand.closing())));
}

}  // namespace antipode::selectors
