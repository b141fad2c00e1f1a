#pragma once
// Synthetic single-view clouds of simple shapes, as a depth sensor at the origin would see
// them: only surface points facing the sensor are kept (exact visibility for convex
// shapes), optionally with Gaussian noise along the viewing ray.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/core/cloud.hpp"

namespace antipode::testing {

struct ShapeOptions {
  double spacing_m = 0.0015;  ///< surface sampling step
  double noise_m = 0.0;       ///< standard deviation of the depth noise
  std::uint64_t seed = 1;
};

/// A cylinder of `diameter_m` and `length_m` around `axis` through `centre_m` (caps included).
Cloud cylinder_cloud(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& axis,
                     double diameter_m, double length_m, const ShapeOptions& options = {});

/// A box with edges `size_m` along the axes of `rotation`, centred at `centre_m`.
Cloud box_cloud(const Eigen::Vector3d& centre_m, const Eigen::Matrix3d& rotation,
                const Eigen::Vector3d& size_m, const ShapeOptions& options = {});

/// A sphere.
Cloud sphere_cloud(const Eigen::Vector3d& centre_m, double diameter_m,
                   const ShapeOptions& options = {});

/// A square of side `side_m` through `centre_m` with normal `normal`.
Cloud plane_cloud(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& normal, double side_m,
                  const ShapeOptions& options = {});

/// Appends `extra`'s points (same single view) to `cloud`.
void append(Cloud& cloud, const Cloud& extra);

}  // namespace antipode::testing
