#pragma once
// Internal to the geometry area: the least-squares plane through a set of points.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "antipode/geometry/support_plane.hpp"

namespace antipode::geometry {

/// Refits `plane` to the points at `indices` (at least 3): the normal is the direction of
/// their least spread, turned to the side of the old normal, and the plane passes through
/// their mean. `spread` receives the in-plane directions of most and of middle spread.
/// False (and nothing changed) for fewer than 3 points or a failed decomposition.
bool refit_plane(const std::vector<Eigen::Vector3f>& points,
                 const std::vector<std::int32_t>& indices, SupportPlane& plane,
                 Eigen::Matrix<float, 3, 2>& spread);

}  // namespace antipode::geometry
