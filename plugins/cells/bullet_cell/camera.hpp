#pragma once
// A pinhole depth camera: intrinsics, range, and its pose in the base frame.

#include <string>

#include <Eigen/Geometry>

namespace antipode::cells {

/// Defaults are the Asus Xtion Pro of the paper (baxter.md).
struct CameraSpec {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d look_at_m = Eigen::Vector3d::UnitX();
  int width_px = 640;
  int height_px = 480;
  double fx_px = 570.3;
  double fy_px = 570.3;
  double cx_px = 319.5;
  double cy_px = 239.5;
  double min_range_m = 0.5;
  double max_range_m = 3.5;
};

/// X_BaseCamera of an optical frame (z forward, x right, y down) at `position` looking at
/// `target`, with the image's up direction towards base +z (or +x when looking straight down).
Eigen::Isometry3d look_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target);

}  // namespace antipode::cells
