#include "collision_shape.hpp"

#include "antipode/core/error.hpp"
#include "hull_shape.hpp"

namespace antipode::cells {

ShapeHolder make_box_shape(const Eigen::Vector3d& h, double margin_m) {
  ShapeHolder holder;
  auto box = std::make_unique<btBoxShape>(btVector3(h.x(), h.y(), h.z()));
  box->setMargin(btScalar(margin_m));
  box->initializePolyhedralFeatures();
  holder.root = std::move(box);
  return holder;
}

ShapeHolder make_collision_shape(const CollisionSpec& spec, double margin_m) {
  ShapeHolder holder;
  switch (spec.kind) {
    case CollisionKind::kBox:
      return make_box_shape(spec.half_extents_m, margin_m);
    case CollisionKind::kCylinder:
      holder.root = std::make_unique<btCylinderShapeZ>(
          btVector3(spec.radius_m, spec.radius_m, spec.half_height_m));
      holder.root->setMargin(btScalar(margin_m));
      return holder;
    case CollisionKind::kSphere:
      holder.root = std::make_unique<btSphereShape>(btScalar(spec.radius_m));
      return holder;
    case CollisionKind::kCapsule:
      holder.root = std::make_unique<btCapsuleShapeZ>(btScalar(spec.radius_m),
                                                      btScalar(2.0 * spec.half_height_m));
      return holder;
    case CollisionKind::kHulls:
      break;
  }
  if (spec.hulls.empty()) throw Error("an object has no collision hull");
  if (spec.hulls.size() == 1) {
    holder.root = std::make_unique<HullShape>(spec.hulls[0], margin_m);
    return holder;
  }
  auto compound = std::make_unique<btCompoundShape>();
  for (const auto& mesh : spec.hulls) {
    holder.children.push_back(std::make_unique<HullShape>(mesh, margin_m));
    btTransform identity;
    identity.setIdentity();
    compound->addChildShape(identity, holder.children.back().get());
  }
  holder.root = std::move(compound);
  return holder;
}

}  // namespace antipode::cells
