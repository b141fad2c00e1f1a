#include "views.hpp"

#include "antipode/core/hand_geometry.hpp"
#include "antipode/geometry/hand_body.hpp"

namespace antipode::testing {

Cloud seen_from(const Shape& shape, const Eigen::Vector3d& centre_m,
                const std::vector<Eigen::Vector3d>& sensors_m) {
  Cloud cloud;
  cloud.frame = "base";
  for (std::size_t v = 0; v < sensors_m.size(); ++v) {
    const Cloud view = shape(centre_m - sensors_m[v]);
    for (const Eigen::Vector3f& p : view.points_m) {
      cloud.points_m.push_back(p + sensors_m[v].cast<float>());
      cloud.view_masks.push_back(1u << v);
    }
    cloud.view_origins_m.push_back(sensors_m[v].cast<float>());
  }
  return cloud;
}

Hand hand_at(const Cloud& cloud, const Eigen::Vector3d& approach, const Eigen::Vector3d& closing,
             const Eigen::Vector3d& palm_m) {
  Hand hand;
  Eigen::Matrix3d rotation;
  rotation.col(0) = approach.normalized();
  rotation.col(1) = closing.normalized();
  rotation.col(2) = rotation.col(0).cross(rotation.col(1));
  hand.X_FrameHand.linear() = rotation;
  hand.X_FrameHand.translation() = palm_m;
  hand.frame = cloud.frame;
  hand.closing_points =
      points_in_closing_region(make_hand_body(HandGeometry{}, 0.01), hand.X_FrameHand, cloud.points_m);
  return hand;
}

}  // namespace antipode::testing
