#pragma once
// An orthographic view for pictures of clouds and hands: a viewing direction, an up hint, a
// centre and a scale. Orthographic rather than perspective so that gripper sizes read the
// same everywhere in the picture.

#include <Eigen/Core>

namespace antipode::pictures {

struct ProjectedPoint {
  double u_px;     ///< column
  double v_px;     ///< row
  double depth_m;  ///< along the viewing direction; larger is further away
};

class OrthoView {
 public:
  /// Looks along `forward` (need not be unit) with `up_hint` pointing up in the picture; the
  /// picture is `size_px` square, centred on `centre_m`, `half_extent_m` from centre to edge.
  OrthoView(const Eigen::Vector3d& forward, const Eigen::Vector3d& up_hint,
            const Eigen::Vector3d& centre_m, double half_extent_m, int size_px);

  ProjectedPoint project(const Eigen::Vector3d& p_m) const;

  /// The view seen after walking 90 degrees around the centre, to the viewer's left.
  OrthoView side_view() const;

  int size_px() const { return size_px_; }
  double px_per_m() const { return px_per_m_; }

 private:
  Eigen::Vector3d forward_, right_, down_, up_hint_, centre_m_;
  double half_extent_m_;
  int size_px_;
  double px_per_m_;
};

}  // namespace antipode::pictures
