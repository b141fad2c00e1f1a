#pragma once
// A graspable object: what the sensor sees (visual mesh), what the physics touches
// (collision shape) and its mass and friction. Both shapes share the object's frame, whose
// origin is the centre of mass.

#include <memory>
#include <string>
#include <vector>

#include "triangle_mesh.hpp"

namespace antipode::cells {

enum class CollisionKind { kBox, kCylinder, kSphere, kCapsule, kHulls };

/// The collision shape. Primitives use Bullet's exact shapes (axis along z); everything else
/// is one convex hull per piece of `hulls`.
struct CollisionSpec {
  CollisionKind kind = CollisionKind::kHulls;
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();  ///< box
  double radius_m = 0.0;                                     ///< cylinder, sphere, capsule
  double half_height_m = 0.0;  ///< cylinder; capsule: half the straight part
  std::vector<TriangleMesh> hulls;
};

struct ObjectModel {
  std::string name;
  std::shared_ptr<const TriangleMesh> visual;
  CollisionSpec collision;
  double mass_kg = 0.1;
  double friction = 0.8;
  /// What a gripper must span to hold the object by its narrowest graspable part: the
  /// smallest extent across z for primitives and meshes, the body diameter of bottles and
  /// mugs, the banana's diameter, the bar width of L and T.
  double graspable_width_m = 0.0;
};

/// Moves `visual` and every hull so that the object's centre of mass is the origin: the
/// visual mesh's volume centroid when it lies inside the mesh's bounding box (a closed
/// surface), else - a scan left open with faces wound both ways, whose signed volume cancels
/// and whose centroid is meaningless - the volume-weighted centroid of the hulls, the solid
/// the physics holds.
void centre_on_mass(TriangleMesh& visual, std::vector<TriangleMesh>& hulls);

}  // namespace antipode::cells
