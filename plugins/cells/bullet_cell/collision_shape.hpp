#pragma once
// Bullet collision shapes for an object's CollisionSpec.

#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "object_model.hpp"

namespace antipode::cells {

/// A shape and the child shapes a compound refers to (Bullet does not own them).
struct ShapeHolder {
  std::unique_ptr<btCollisionShape> root;
  std::vector<std::unique_ptr<btCollisionShape>> children;
};

/// Primitives become Bullet's exact shapes; hulls one HullShape each (a compound
/// when there is more than one). Convex margins are set to `margin_m`.
ShapeHolder make_collision_shape(const CollisionSpec& spec, double margin_m);

ShapeHolder make_box_shape(const Eigen::Vector3d& half_extents_m, double margin_m);

}  // namespace antipode::cells
