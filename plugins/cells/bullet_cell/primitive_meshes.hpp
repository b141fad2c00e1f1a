#pragma once
// Closed triangle meshes of simple solids, centred on the origin, long axis along z.

#include <cstddef>
#include <vector>

#include "triangle_mesh.hpp"

namespace antipode::cells {

TriangleMesh box_mesh(const Eigen::Vector3f& half_extents_m);
TriangleMesh cylinder_mesh(float radius_m, float height_m, int segments = 32);
/// An ellipsoid with semi-axes `radii_m` (a sphere when they are equal).
TriangleMesh ellipsoid_mesh(const Eigen::Vector3f& radii_m, int segments = 24);
/// A cylinder of `cylinder_height_m` capped by two hemispheres of `radius_m`.
TriangleMesh capsule_mesh(float radius_m, float cylinder_height_m, int segments = 24);
/// A surface of revolution about z through profile points (radius, z), from the bottom
/// (radius 0) to the top (radius 0).
TriangleMesh revolution_mesh(const std::vector<Eigen::Vector2f>& profile, int segments = 32);

/// One cross-section of a swept solid: a circle of `radius_m` about `centre_m` in the plane
/// spanned by the unit axes `u` and `v` (radius 0: a single point, the end of the solid).
/// u x v must point the way the sweep runs, so that the surface faces outwards.
struct SweepRing {
  Eigen::Vector3f centre_m;
  Eigen::Vector3f u, v;
  float radius_m;
};
/// The surface through `rings` in order, each sampled at `segments` points. The first and
/// last ring must have radius 0 for the mesh to be closed.
TriangleMesh sweep_mesh(const std::vector<SweepRing>& rings, int segments);
/// `rings` [first, last] closed by flat caps: a convex piece of a tube when the rings lie
/// on a gently curved path.
TriangleMesh sweep_piece(const std::vector<SweepRing>& rings, std::size_t first, std::size_t last,
                         int segments);

}  // namespace antipode::cells
