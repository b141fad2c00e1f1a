#pragma once
// Points on the true surfaces of a world, for pictures of what the gripper met.
//
// A failed attempt's picture draws the cloud the grasp was found in: the sensors' view
// before the attempt, noisy, with the far side of every object missing. Where the object
// really was when the fingers closed - pushed aside, tipped, rolled out from between them -
// only the simulation knows. These samples of its meshes let a picture show it.

#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "physics_world.hpp"

namespace antipode::cells {

/// Points on the world's visible meshes (objects, box, table) inside the box centred at
/// X_BaseRegion with half-sides `half_extents_m` along its axes, in the base frame. Each
/// triangle is sampled on a grid along two of its edges, each cut into steps of at most
/// `spacing_m` (about one point per `spacing_m` squared, however long and thin the
/// triangle); a triangle no wider than `spacing_m` gives its centroid; triangles whose
/// bounds miss the region are skipped. At most `max_points`: past that, the rest of the
/// world is not sampled (raise the spacing for a large region).
std::vector<Eigen::Vector3f> surface_points_near(const PhysicsWorld& world,
                                                 const Eigen::Isometry3d& X_BaseRegion,
                                                 const Eigen::Vector3d& half_extents_m,
                                                 double spacing_m, std::size_t max_points);

/// The same for one mesh placed at X_BaseMesh (the grid and the region as above), appended
/// to `out` until it holds `max_points`.
void sample_mesh_near(const TriangleMesh& mesh, const Eigen::Isometry3d& X_BaseMesh,
                      const Eigen::Isometry3d& X_BaseRegion, const Eigen::Vector3d& half_extents_m,
                      double spacing_m, std::size_t max_points, std::vector<Eigen::Vector3f>& out);

}  // namespace antipode::cells
