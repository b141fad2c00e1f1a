#pragma once
// Internal to the geometry area: whether a plane is a surface seen face-on.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "antipode/geometry/point_index.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode::geometry {

/// The fraction of the plane's inliers (within `distance_m`, among `points`) where the
/// cloud's surface faces along the plane's normal: the local normal (PCA of the `points`
/// within 1.5 cm) within 25 degrees of it, over up to 128 inliers spread over the plane with
/// enough neighbours. A table is a surface seen face-on; the band a plane cuts from the rim
/// of a convex object seen from one side is not: there the surface runs across the plane.
/// Costs one pass over `points` per probe: give an even subset of a large cloud.
double facing_fraction(const std::vector<Eigen::Vector3f>& points, const SupportPlane& plane,
                       float distance_m);

/// The same over `inliers` (indices into `points`), each probe's neighbourhood found with
/// `index` (over `points`), so a large cloud needs no subset.
double facing_fraction(const std::vector<Eigen::Vector3f>& points, const PointIndex& index,
                       const std::vector<std::int32_t>& inliers, const SupportPlane& plane);

}  // namespace antipode::geometry
