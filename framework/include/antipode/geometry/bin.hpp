#pragma once
/// @file
/// A bin the objects lie in - a clutter box - known from the cell's layout: an axis-aligned
/// rectangle of walls standing on a floor. Its walls are a fixture, never an object: the
/// sampler's scene stage keeps their points out of every object (scene_layout.hpp), and the
/// cluster selector drops hands that reach into them. One description serves both, so that
/// a tree names its box once (`bin:` in the selector, `scene.bin:` in the sampler).
///
/// Units: metres; frame: the cloud's (the hands'), with z up. Plain values: thread-safe.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/core/parameters.hpp"
#include "antipode/geometry/axis_box.hpp"

namespace antipode {

/// The inner size of the box, centred on `center_m`, with walls `wall_height_m` high standing
/// on `floor_z_m` and `wall_thickness_m` thick outside the inner size.
struct Bin {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d inner_size_m = Eigen::Vector2d::Zero();
  double floor_z_m = 0.0;
  double wall_height_m = 0.06;
  double wall_thickness_m = 0.01;

  /// The four walls as solid boxes, in the order -y, +y, -x, +x: the two at -y and +y span
  /// the corners, the two at -x and +x lie between them.
  std::array<Eigen::AlignedBox3d, 4> walls() const;

  /// The walls as fixtures of the scene stage: each wall grown by `inward_m` on its face
  /// towards the box's inside and by `outward_m` on every other side, so that a wall's points,
  /// scattered by the sensor's noise, stay out of the objects.
  std::vector<AxisBox> fixtures(double inward_m, double outward_m) const;
};

/// Reads `{center_m: [x, y], inner_size_m: [x, y], floor_z_m, wall_height_m,
/// wall_thickness_m}` (the first two required); throws antipode::Error naming the key and its
/// place in the file for a missing, malformed or out-of-range value, or an unknown key.
Bin read_bin(const Parameters& p);

}  // namespace antipode
