#pragma once
/// @file
/// Which space a cloud's sensors could see: a point is hidden when, in every view, an
/// observed surface lies in front of it along the ray from the sensor.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"

namespace antipode {

/// One depth image per view, rebuilt from the cloud's points.
///
/// Each view's points (those whose view mask has the view's bit; all points when the cloud
/// has no masks) are projected through its origin onto an image plane facing their mean
/// direction, each point covering a disc of `point_radius_m` (so that a surface sampled
/// every few millimetres has no holes), and every pixel keeps the nearest range. Points more
/// than about 78 degrees off that mean direction are left out. Pixels no point covers count
/// as free space (the sensor saw nothing there).
class OcclusionMap {
 public:
  /// A cloud without view origins gives a map in which nothing is hidden.
  OcclusionMap(const Cloud& cloud, float point_radius_m);
  ~OcclusionMap();
  OcclusionMap(OcclusionMap&&) noexcept;
  OcclusionMap& operator=(OcclusionMap&&) noexcept;

  /// True when every view has an observed surface more than `margin_m` nearer than `p`
  /// along the ray to `p` (false for a point outside every view's image).
  bool hidden(const Eigen::Vector3f& p, float margin_m) const;

 private:
  struct View;
  std::vector<std::unique_ptr<View>> views_;
};

}  // namespace antipode
