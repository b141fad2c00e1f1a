#pragma once
// Closed triangle meshes of simple solids, centred on the origin, long axis along z.

#include "triangle_mesh.hpp"

namespace antipode::cells {

TriangleMesh box_mesh(const Eigen::Vector3f& half_extents_m);
TriangleMesh cylinder_mesh(float radius_m, float height_m, int segments = 32);
/// An ellipsoid with semi-axes `radii_m` (a sphere when they are equal).
TriangleMesh ellipsoid_mesh(const Eigen::Vector3f& radii_m, int segments = 24);
/// A cylinder of `cylinder_height_m` capped by two hemispheres of `radius_m`.
TriangleMesh capsule_mesh(float radius_m, float cylinder_height_m, int segments = 24);

}  // namespace antipode::cells
