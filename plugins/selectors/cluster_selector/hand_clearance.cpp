#include "hand_clearance.hpp"

#include <algorithm>
#include <cmath>

#include "antipode/geometry/hand_body.hpp"

namespace antipode::selectors {

bool clears_support(const Hand& hand, const HandGeometry& geometry, const SupportPlane& support,
                    double standoff_m, double clearance_m) {
  const HandBody body = make_hand_body(geometry);
  const Eigen::Vector3d lo(body.palm.min_m.x() - standoff_m, body.palm.min_m.y(),
                           body.palm.min_m.z());
  const Eigen::Vector3d hi(body.depth_m, body.palm.max_m.y(), body.palm.max_m.z());
  const Eigen::Vector3d normal = support.normal.cast<double>();
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                            (corner & 4) ? hi.z() : lo.z());
    if (normal.dot(hand.X_FrameHand * p) + double(support.offset) < clearance_m) return false;
  }
  return true;
}

bool approach_is_free(const Hand& hand, const HandGeometry& geometry, const Cloud& cloud,
                      double standoff_m) {
  const HandBody body = make_hand_body(geometry);
  const double palm_face_gap_m = 0.001;
  const Eigen::Isometry3f X_HandFrame = hand.X_FrameHand.inverse().cast<float>();
  const float back = float(body.palm.min_m.x() - standoff_m);
  const float front = float(-palm_face_gap_m);
  const float half_width = float(body.palm.max_m.y());
  const float half_height = float(body.half_height_m);
  for (const Eigen::Vector3f& point : cloud.points_m) {
    const Eigen::Vector3f p = X_HandFrame * point;
    if (std::abs(p.z()) > half_height || std::abs(p.y()) > half_width) continue;
    if (p.x() >= back && p.x() <= front) return false;  // in the palm or its sweep
    if (body.collides(p.cast<double>())) return false;  // in a finger
  }
  return true;
}

bool way_in_is_seen(const Hand& hand, const HandGeometry& geometry, const OcclusionMap& occlusion,
                    double standoff_m, float margin_m) {
  const HandBody body = make_hand_body(geometry);
  const double step_m = 0.01;
  const double finger_y = (body.finger_plus_y.min_m.y() + body.finger_plus_y.max_m.y()) / 2;
  const double back_m = standoff_m - body.palm.min_m.x();  // the palm's back at the stand-off
  const int steps = int(std::floor(back_m / step_m + 1e-9));
  for (int i = 1; i <= steps; ++i)
    for (const double y : {-finger_y, 0.0, finger_y}) {
      const Eigen::Vector3d p = hand.X_FrameHand * Eigen::Vector3d(-i * step_m, y, 0.0);
      if (occlusion.hidden(p.cast<float>(), margin_m)) return false;
    }
  return true;
}

}  // namespace antipode::selectors
