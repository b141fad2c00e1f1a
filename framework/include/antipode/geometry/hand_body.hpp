#pragma once
/// @file
/// The gripper as boxes in the hand frame, and exact point tests against them.
///
/// Hand frame (docs/pose-convention.md): x = approach, y = closing, z = axis; the origin is
/// the centre of the palm face. With a = max_aperture_m, w = finger_width_m,
/// d = depth_m, h = height_m, o = outer_diameter_m and t = palm thickness:
///   closing region  x in [0, d],   |y| <  a/2,              |z| <= h/2
///   finger at -y    x in [0, d],   y in [-a/2 - w, -a/2],   |z| <= h/2
///   finger at +y    x in [0, d],   y in [a/2, a/2 + w],     |z| <= h/2
///   palm            x in [-t, 0],  |y| <= max(o/2, a/2 + w), |z| <= h/2
/// Finger and palm boxes are closed (a point on a face collides); the closing region is
/// open towards the fingers.

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"

namespace antipode {

/// A closed axis-aligned box in hand coordinates.
struct HandBox {
  Eigen::Vector3d min_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d max_m = Eigen::Vector3d::Zero();

  bool contains(const Eigen::Vector3d& p_hand) const {
    return (p_hand.array() >= min_m.array()).all() && (p_hand.array() <= max_m.array()).all();
  }
};

/// The three boxes of the hand body and the closing region, in hand coordinates.
struct HandBody {
  HandBox finger_minus_y;
  HandBox finger_plus_y;
  HandBox palm;
  double half_aperture_m = 0.0;
  double depth_m = 0.0;
  double half_height_m = 0.0;

  /// True when `p_hand` is in a finger or the palm.
  bool collides(const Eigen::Vector3d& p_hand) const {
    return finger_minus_y.contains(p_hand) || finger_plus_y.contains(p_hand) ||
           palm.contains(p_hand);
  }
  /// True when `p_hand` is in the closing region (between the fingers).
  bool in_closing_region(const Eigen::Vector3d& p_hand) const {
    return p_hand.x() >= 0.0 && p_hand.x() <= depth_m && std::abs(p_hand.y()) < half_aperture_m &&
           std::abs(p_hand.z()) <= half_height_m;
  }
};

/// The body of a hand of `geometry` (its palm is `geometry.palm_thickness_m` thick).
HandBody make_hand_body(const HandGeometry& geometry);

/// The same with another palm thickness (0: the fingers and closing region alone).
HandBody make_hand_body(const HandGeometry& geometry, double palm_thickness_m);

/// The middle of the closing region of `hand` (where the fingers hold an object), in the
/// hand's frame's parent (`hand.frame`).
Eigen::Vector3d grasp_centre(const Hand& hand, const HandGeometry& geometry);

/// Indices of the points of `points` (in the frame of `X_FrameHand`) that lie in the body
/// of the hand at pose `X_FrameHand`. Exact for the box model; a brute-force reference for
/// tests and tools (it visits every point).
std::vector<std::int32_t> points_in_collision(const HandBody& body,
                                              const Eigen::Isometry3d& X_FrameHand,
                                              const std::vector<Eigen::Vector3f>& points);

/// Indices of the points of `points` inside the closing region of the hand at X_FrameHand.
std::vector<std::int32_t> points_in_closing_region(const HandBody& body,
                                                   const Eigen::Isometry3d& X_FrameHand,
                                                   const std::vector<Eigen::Vector3f>& points);

}  // namespace antipode
