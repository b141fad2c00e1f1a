#include "gripper.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyFixedConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyGearConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <btBulletDynamicsCommon.h>

#include "bullet_convert.hpp"

namespace antipode::cells {
namespace {

Eigen::Isometry3d offset(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

}  // namespace

// The Bullet objects of one gripper: the multibody (base = palm, links 0 and 1 = the fingers
// at -y and +y), one box shape and collider per part, and the constraints.
struct Gripper::Parts {
  std::unique_ptr<btMultiBody> body;
  std::unique_ptr<btBoxShape> palm_shape;
  std::vector<std::unique_ptr<btCollisionShape>> finger_parts;  // owned children of compounds
  btCollisionShape* finger_shapes[2] = {nullptr, nullptr};
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;  // palm, finger -y, +y
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints;
  btMultiBodyFixedConstraint* drive = nullptr;
  btMultiBodyJointMotor* motors[2] = {nullptr, nullptr};
};

namespace {

// A finger: a box with a half-round tip (Baxter's fingers end in half cylinders), in the
// finger's frame (its box centre). A rounded tip slides over an edge or a curved surface
// where a box corner catches and jolts; the tip's cylinder runs along the hand axis.
btCollisionShape* finger_shape(const HandGeometry& g, btScalar margin, Gripper::Parts& p);

}  // namespace

Gripper::Gripper(PhysicsWorld& world, const GripperOptions& options,
                 const Eigen::Isometry3d& X_BaseHand)
    : world_(world), options_(options), X_BaseHand_(X_BaseHand), parts_(std::make_unique<Parts>()) {
  const HandGeometry& g = options.geometry;
  const double t = g.palm_thickness_m;
  const double dt = world.options().time_step_s;
  const double palm_half_y =
      std::max(g.outer_diameter_m, g.max_aperture_m + 2 * g.finger_width_m) / 2;
  const btVector3 palm_half(btScalar(t / 2), btScalar(palm_half_y), btScalar(g.height_m / 2));
  const btVector3 finger_half(btScalar(g.depth_m / 2), btScalar(g.finger_width_m / 2),
                              btScalar(g.height_m / 2));
  Parts& p = *parts_;
  const btScalar margin = btScalar(world.options().margin_m);
  p.palm_shape = std::make_unique<btBoxShape>(palm_half);
  p.palm_shape->setMargin(margin);
  for (int side = 0; side < 2; ++side) p.finger_shapes[side] = finger_shape(g, margin, p);
  btVector3 palm_inertia, finger_inertia;
  p.palm_shape->calculateLocalInertia(btScalar(options.palm_mass_kg), palm_inertia);
  btBoxShape(finger_half).calculateLocalInertia(btScalar(options.finger_mass_kg), finger_inertia);

  // Base frame: the palm box's centre, t/2 behind the palm face. Finger joints move inwards:
  // joint position 0 is fully open, positive closes.
  p.body =
      std::make_unique<btMultiBody>(2, btScalar(options.palm_mass_kg), palm_inertia, false, false);
  p.body->setBaseWorldTransform(to_bullet(X_BaseHand * offset(-t / 2, 0, 0)));
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1.0 : 1.0;
    const btVector3 pivot(btScalar(g.depth_m / 2 + t / 2),
                          btScalar(sign * (g.max_aperture_m + g.finger_width_m) / 2), 0);
    p.body->setupPrismatic(side, btScalar(options.finger_mass_kg), finger_inertia, -1,
                           btQuaternion::getIdentity(), btVector3(0, btScalar(-sign), 0), pivot,
                           btVector3(0, 0, 0), true);
  }
  p.body->finalizeMultiDof();
  p.body->setHasSelfCollision(false);
  p.body->setCanSleep(false);
  p.body->setLinearDamping(0);
  p.body->setAngularDamping(0);
  btMultiBodyDynamicsWorld& dynamics = world.dynamics();
  dynamics.addMultiBody(p.body.get());

  const char* names[] = {"palm", "finger -y", "finger +y"};
  for (int part = 0; part < 3; ++part) {
    auto collider = std::make_unique<btMultiBodyLinkCollider>(p.body.get(), part - 1);
    collider->setCollisionShape(part == 0 ? static_cast<btCollisionShape*>(p.palm_shape.get())
                                          : p.finger_shapes[part - 1]);
    collider->setFriction(btScalar(options.friction));
    collider->setSpinningFriction(btScalar(options.torsional_friction_m));
    dynamics.addCollisionObject(collider.get(), btBroadphaseProxy::DefaultFilter,
                                btBroadphaseProxy::AllFilter);
    if (part == 0)
      p.body->setBaseCollider(collider.get());
    else
      p.body->getLink(part - 1).m_collider = collider.get();
    const int id = world.register_part(collider.get(), BodyRole::kGripper, names[part]);
    (part == 0 ? palm_ : fingers_[part - 1]) = id;
    p.colliders.push_back(std::move(collider));
  }
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> origins;
  p.body->forwardKinematics(rotations, origins);
  p.body->updateCollisionObjectWorldTransforms(rotations, origins);

  const btScalar stroke = btScalar((g.max_aperture_m - g.min_aperture_m) / 2);
  for (int side = 0; side < 2; ++side) {
    p.constraints.push_back(
        std::make_unique<btMultiBodyJointLimitConstraint>(p.body.get(), side, 0, stroke));
    auto motor = std::make_unique<btMultiBodyJointMotor>(p.body.get(), side, 0,
                                                         btScalar(-options.finger_speed_m_s),
                                                         btScalar(options.finger_force_n * dt));
    p.motors[side] = motor.get();
    p.constraints.push_back(std::move(motor));
  }
  // The gear: both fingers travel alike (joint velocity 0 + ratio x joint velocity 1 = 0).
  auto gear = std::make_unique<btMultiBodyGearConstraint>(
      p.body.get(), 0, p.body.get(), 1, btVector3(0, 0, 0), btVector3(0, 0, 0),
      btMatrix3x3::getIdentity(), btMatrix3x3::getIdentity());
  gear->setGearRatio(-1);
  gear->setErp(0.2f);
  gear->setMaxAppliedImpulse(btScalar(options.hand_force_n * dt));
  p.constraints.push_back(std::move(gear));
  auto carrier = std::make_unique<btMultiBodyFixedConstraint>(
      p.body.get(), -1, static_cast<btRigidBody*>(nullptr), btVector3(0, 0, 0), btVector3(0, 0, 0),
      btMatrix3x3::getIdentity(), btMatrix3x3::getIdentity());
  carrier->setMaxAppliedImpulse(btScalar(options.hand_force_n * dt));
  p.drive = carrier.get();
  p.constraints.push_back(std::move(carrier));
  for (auto& constraint : p.constraints) dynamics.addMultiBodyConstraint(constraint.get());
  drive();
  world.set_before_step([this] { drive(); });
}

Gripper::~Gripper() {
  world_.set_before_step({});
  btMultiBodyDynamicsWorld& dynamics = world_.dynamics();
  Parts& p = *parts_;
  for (auto& constraint : p.constraints) dynamics.removeMultiBodyConstraint(constraint.get());
  for (auto& collider : p.colliders) dynamics.removeCollisionObject(collider.get());
  dynamics.removeMultiBody(p.body.get());
  for (int id : {palm_, fingers_[0], fingers_[1]}) world_.unregister_part(id);
}

namespace {

btCollisionShape* finger_shape(const HandGeometry& g, btScalar margin, Gripper::Parts& p) {
  const double r = g.finger_width_m / 2;
  const double box_depth = g.depth_m - r;
  auto box = std::make_unique<btBoxShape>(
      btVector3(btScalar(box_depth / 2), btScalar(r), btScalar(g.height_m / 2)));
  auto tip = std::make_unique<btCylinderShapeZ>(
      btVector3(btScalar(r), btScalar(r), btScalar(g.height_m / 2)));
  box->setMargin(margin);
  tip->setMargin(margin);
  auto finger = std::make_unique<btCompoundShape>();
  btTransform at;
  at.setIdentity();
  at.setOrigin(btVector3(btScalar(-g.depth_m / 2 + box_depth / 2), 0, 0));
  finger->addChildShape(at, box.get());
  at.setOrigin(btVector3(btScalar(g.depth_m / 2 - r), 0, 0));
  finger->addChildShape(at, tip.get());
  btCollisionShape* shape = finger.get();
  p.finger_parts.push_back(std::move(box));
  p.finger_parts.push_back(std::move(tip));
  p.finger_parts.push_back(std::move(finger));
  return shape;
}

}  // namespace

void Gripper::move_to(const Eigen::Isometry3d& X_BaseHand) { X_BaseHand_ = X_BaseHand; }

Eigen::Isometry3d Gripper::actual_pose() const {
  return from_bullet(parts_->body->getBaseWorldTransform()) *
         offset(options_.geometry.palm_thickness_m / 2, 0, 0);
}

void Gripper::drive() {
  Parts& p = *parts_;
  const Eigen::Isometry3d target =
      X_BaseHand_ * offset(-options_.geometry.palm_thickness_m / 2, 0, 0);
  p.drive->setPivotInB(to_bullet(target.translation()));
  p.drive->setFrameInB(to_bullet(target).getBasis());
  // The arm carries the hand: cancel gravity on the palm and the fingers.
  const btVector3 gravity = world_.dynamics().getGravity();
  p.body->addBaseForce(-gravity * p.body->getBaseMass());
  for (int side = 0; side < 2; ++side)
    p.body->addLinkForce(side, -gravity * p.body->getLinkMass(side));
}

void Gripper::drive_fingers(double velocity_m_s) {
  for (auto* motor : parts_->motors) motor->setVelocityTarget(btScalar(-velocity_m_s));
}

double Gripper::finger_travel_m(int side) const { return parts_->body->getJointPos(side); }

double Gripper::aperture_m() const {
  return options_.geometry.max_aperture_m - finger_travel_m(0) - finger_travel_m(1);
}

std::set<int> Gripper::touching(double tolerance_m) const {
  std::set<int> found;
  for (const auto& [part, id] : touching_parts(tolerance_m)) found.insert(id);
  return found;
}

std::vector<std::pair<std::string, int>> Gripper::touching_parts(double tolerance_m) const {
  const std::pair<const char*, int> parts[] = {
      {"palm", palm_}, {"finger -y", fingers_[0]}, {"finger +y", fingers_[1]}};
  std::vector<std::pair<std::string, int>> found;
  for (const auto& [name, part] : parts)
    for (int id : world_.touching(part, tolerance_m))
      if (id >= 0 && world_.has(id) && world_.role(id) != BodyRole::kGripper)
        found.emplace_back(name, id);
  return found;
}

std::set<int> Gripper::pinched(double tolerance_m) const {
  // The simulation's own contact manifolds: what the fingers press on in this step.
  std::set<int> by_finger[2];
  for (const auto& [a, b] : world_.contacts(tolerance_m))
    for (int side = 0; side < 2; ++side) {
      if (a == fingers_[side]) by_finger[side].insert(b);
      if (b == fingers_[side]) by_finger[side].insert(a);
    }
  std::set<int> both;
  for (int id : by_finger[0])
    if (by_finger[1].count(id) && world_.has(id) && world_.role(id) == BodyRole::kObject)
      both.insert(id);
  return both;
}

}  // namespace antipode::cells
