#include "antipode/geometry/hand_body.hpp"

#include <algorithm>

namespace antipode {
namespace {

template <typename Test>
std::vector<std::int32_t> points_where(const Eigen::Isometry3d& X_FrameHand,
                                       const std::vector<Eigen::Vector3f>& points, Test test) {
  const Eigen::Isometry3d X_HandFrame = X_FrameHand.inverse();
  std::vector<std::int32_t> found;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (test(X_HandFrame * points[i].cast<double>())) found.push_back(static_cast<std::int32_t>(i));
  }
  return found;
}

}  // namespace

HandBody make_hand_body(const HandGeometry& geometry) {
  return make_hand_body(geometry, geometry.palm_thickness_m);
}

HandBody make_hand_body(const HandGeometry& geometry, double palm_thickness_m) {
  const double a = geometry.max_aperture_m / 2.0;
  const double w = geometry.finger_width_m;
  const double d = geometry.depth_m;
  const double h = geometry.height_m / 2.0;
  const double palm_half_width = std::max(geometry.outer_diameter_m / 2.0, a + w);
  HandBody body;
  body.finger_minus_y = {{0.0, -a - w, -h}, {d, -a, h}};
  body.finger_plus_y = {{0.0, a, -h}, {d, a + w, h}};
  body.palm = {{-palm_thickness_m, -palm_half_width, -h}, {0.0, palm_half_width, h}};
  body.half_aperture_m = a;
  body.depth_m = d;
  body.half_height_m = h;
  return body;
}

std::vector<std::int32_t> points_in_collision(const HandBody& body,
                                              const Eigen::Isometry3d& X_FrameHand,
                                              const std::vector<Eigen::Vector3f>& points) {
  return points_where(X_FrameHand, points,
                      [&body](const Eigen::Vector3d& p) { return body.collides(p); });
}

std::vector<std::int32_t> points_in_closing_region(const HandBody& body,
                                                   const Eigen::Isometry3d& X_FrameHand,
                                                   const std::vector<Eigen::Vector3f>& points) {
  return points_where(X_FrameHand, points,
                      [&body](const Eigen::Vector3d& p) { return body.in_closing_region(p); });
}

Eigen::Vector3d grasp_centre(const Hand& hand, const HandGeometry& geometry) {
  return hand.X_FrameHand * Eigen::Vector3d(geometry.depth_m / 2, 0.0, 0.0);
}

}  // namespace antipode
