#pragma once
/// @file
/// The surface the objects stand on: the dominant plane of a cloud with (almost) the whole
/// cloud on its sensor side. The hand search treats it as a solid half-space: no sample is
/// drawn from it and no hand body may reach below it (docs/sampling.md, "Support plane").

#include <cstddef>
#include <optional>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"

namespace antipode {

/// The plane {p : normal . p + offset = 0}; `normal` is a unit vector pointing to the free
/// side (towards the sensors).
struct SupportPlane {
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  float offset = 0.0f;
  std::size_t inliers = 0;  ///< cloud points within the search's distance of the plane

  /// Signed distance of `p` from the plane, positive on the free side.
  float distance(const Eigen::Vector3f& p) const { return normal.dot(p) + offset; }
};

struct SupportPlaneOptions {
  /// Points this close to a plane belong to it (sensor noise plus the voxel size).
  float distance_m = 0.01f;
  /// A support is the dominant surface: it holds at least this fraction of the cloud's
  /// points (the rim of a single view of a ball or a can holds a third of it) ...
  float min_inlier_fraction = 0.5f;
  std::size_t min_inliers = 200;
  /// ... and at most this fraction lies more than `distance_m` behind it (objects stand on
  /// a support; a plane cutting through an object, or an object's own face, has much of
  /// the object behind it).
  float max_below_fraction = 0.02f;
  /// ... and at least this fraction lies more than `distance_m` above it (something stands
  /// on a support; a plane alone, such as the one face a sensor sees of a box, is an object)
  float min_above_fraction = 0.01f;
  /// ... and at least this fraction of the points above it have their foot within the
  /// rectangle bounding its inliers (objects stand on a support; a plane tangent to a
  /// convex object has most of the object beside it).
  float min_supported_fraction = 0.8f;
  /// ... and is a surface seen face-on: at least this fraction of its inliers have a local
  /// surface normal within 25 degrees of the plane's (the band a plane cuts from the rim of
  /// a ball or a box seen from one side has the surface running across the plane).
  float min_facing_fraction = 0.6f;
  /// Plane hypotheses tried (each from three random points).
  int iterations = 300;
};

/// Finds the support plane by RANSAC: planes through three random points of `cloud` are
/// scored by their inliers among an evenly strided subset of at most 4,096 points, the best
/// admissible one (oriented towards `toward_sensor`, a point on the sensors' side, and with
/// little of the cloud behind it) is refitted to all its inliers by least squares and
/// checked again on the whole cloud, including the footprint test. Returns nothing when no plane qualifies (a segmented
/// object, a cloud without a dominant flat surface). Deterministic for a given `random`.
std::optional<SupportPlane> find_support_plane(const Cloud& cloud,
                                               const Eigen::Vector3f& toward_sensor,
                                               const SupportPlaneOptions& options,
                                               RandomStream random);

}  // namespace antipode
