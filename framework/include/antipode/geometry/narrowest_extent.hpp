#pragma once
/// @file
/// How wide an object is for a gripper that closes horizontally.

#include <vector>

#include <Eigen/Core>

namespace antipode {

/// The least extent of `points_m` along a horizontal direction (perpendicular to +z of their
/// frame), over all such directions: the width of the narrowest vertical slot the points
/// pass through - the opening a parallel gripper closing horizontally needs to hold them
/// whole. An object lying on a table is held from above only when this lies within the
/// gripper's aperture. Exact: the minimum width of the convex hull of the points projected on
/// the xy plane, which has a side of the slot flush with a hull edge (rotating calipers).
///
/// Metres, in the points' frame; 0 for points that project onto one line or fewer.
/// Pure; thread-safe. O(n log n + h^2) for n points and h hull vertices.
double narrowest_horizontal_extent_m(const std::vector<Eigen::Vector3d>& points_m);

}  // namespace antipode
