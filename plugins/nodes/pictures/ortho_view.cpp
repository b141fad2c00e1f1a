#include "ortho_view.hpp"

#include <Eigen/Geometry>

namespace antipode::pictures {

OrthoView::OrthoView(const Eigen::Vector3d& forward, const Eigen::Vector3d& up_hint,
                     const Eigen::Vector3d& centre_m, double half_extent_m, int size_px)
    : forward_(forward.normalized()),
      up_hint_(up_hint.normalized()),
      centre_m_(centre_m),
      half_extent_m_(half_extent_m),
      size_px_(size_px),
      px_per_m_(0.5 * size_px / half_extent_m) {
  Eigen::Vector3d right = forward_.cross(up_hint_);
  if (right.norm() < 1e-6) right = forward_.unitOrthogonal();  // looking straight up or down
  right_ = right.normalized();
  down_ = forward_.cross(right_);
}

ProjectedPoint OrthoView::project(const Eigen::Vector3d& p_m) const {
  const Eigen::Vector3d d = p_m - centre_m_;
  return {0.5 * size_px_ + px_per_m_ * d.dot(right_), 0.5 * size_px_ + px_per_m_ * d.dot(down_),
          d.dot(forward_)};
}

OrthoView OrthoView::side_view() const {
  return OrthoView(right_, up_hint_, centre_m_, half_extent_m_, size_px_);
}

}  // namespace antipode::pictures
