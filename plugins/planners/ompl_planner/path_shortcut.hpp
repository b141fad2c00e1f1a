#pragma once
// Shortening a joint-space path by shortcuts: from each kept waypoint, jump to the farthest
// later waypoint that a free straight segment reaches. Deterministic, unlike OMPL's
// PathSimplifier, whose random shortcuts draw from the process-wide seed sequence.

#include <vector>

#include <Eigen/Core>

#include "arm_collision_world.hpp"

namespace antipode::planning {

/// The shortened path: a subsequence of `path` with the same ends whose segments are free
/// (segment_is_free at `resolution_rad`, as a rake unless `rake` is false: the same path).
/// Paths of one or two waypoints come back unchanged.
std::vector<Eigen::VectorXd> shortcut_path(const collision::ArmCollisionWorld& world,
                                           const std::vector<Eigen::VectorXd>& path,
                                           double resolution_rad, bool rake = true);

}  // namespace antipode::planning
