#pragma once
// Internal to the geometry area: the convex hull of points in the plane.

#include <vector>

#include <Eigen/Core>

namespace antipode::geometry {

/// The convex hull of `points`, counter-clockwise, without collinear points (Andrew's
/// monotone chain, O(n log n)); fewer than three points come back sorted as they are.
std::vector<Eigen::Vector2f> convex_hull(std::vector<Eigen::Vector2f> points);

}  // namespace antipode::geometry
