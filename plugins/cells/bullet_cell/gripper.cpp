#include "gripper.hpp"

#include <btBulletDynamicsCommon.h>

#include "bullet_convert.hpp"

namespace antipode::cells {
namespace {

Eigen::Isometry3d offset(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

}  // namespace

Gripper::Gripper(PhysicsWorld& world, const GripperOptions& options,
                 const Eigen::Isometry3d& X_BaseHand)
    : world_(world), options_(options), X_BaseHand_(X_BaseHand) {
  const HandGeometry& g = options.geometry;
  const double t = options.palm_thickness_m;
  const double palm_half_y =
      std::max(g.outer_diameter_m, g.max_aperture_m + 2 * g.finger_width_m) / 2;
  palm_ =
      world.add_gripper_box(X_BaseHand * offset(-t / 2, 0, 0), {t / 2, palm_half_y, g.height_m / 2},
                            options.palm_mass_kg, options.friction);
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1.0 : 1.0;
    const double y = sign * (g.max_aperture_m + g.finger_width_m) / 2;
    fingers_[side] = world.add_gripper_box(X_BaseHand * offset(g.depth_m / 2, y, 0),
                                           {g.depth_m / 2, g.finger_width_m / 2, g.height_m / 2},
                                           options.finger_mass_kg, options.friction);
    // The slider's axis (its frame's x) points outwards along the closing direction, so
    // negative travel closes either finger.
    btTransform in_palm, in_finger;
    in_palm.setIdentity();
    in_palm.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(sign * SIMD_HALF_PI)));
    in_palm.setOrigin(btVector3(btScalar(g.depth_m / 2 + t / 2), btScalar(y), 0));
    in_finger.setIdentity();
    in_finger.setRotation(in_palm.getRotation());
    auto* slider = new btSliderConstraint(world.body(palm_), world.body(fingers_[side]), in_palm,
                                          in_finger, true);
    slider->setLowerLinLimit(btScalar(-(g.max_aperture_m - g.min_aperture_m) / 2));
    slider->setUpperLinLimit(0);
    slider->setLowerAngLimit(0);
    slider->setUpperAngLimit(0);
    slider->setPoweredLinMotor(true);
    slider->setMaxLinMotorForce(btScalar(options.finger_force_n));
    slider->setTargetLinMotorVelocity(btScalar(options.finger_speed_m_s));
    world.add_constraint(slider);
    sliders_[side] = slider;
  }
  world.set_before_step([this] { drive(); });
}

Gripper::~Gripper() {
  world_.set_before_step({});
  world_.remove_constraints();
  world_.remove_body(fingers_[0]);
  world_.remove_body(fingers_[1]);
  world_.remove_body(palm_);
}

void Gripper::move_to(const Eigen::Isometry3d& X_BaseHand) { X_BaseHand_ = X_BaseHand; }

Eigen::Isometry3d Gripper::actual_pose() const {
  return world_.pose(palm_) * offset(options_.palm_thickness_m / 2, 0, 0);
}

void Gripper::drive() {
  btRigidBody& palm = world_.body(palm_);
  const double dt = world_.options().time_step_s;
  const Eigen::Isometry3d target = X_BaseHand_ * offset(-options_.palm_thickness_m / 2, 0, 0);
  const Eigen::Isometry3d now = world_.pose(palm_);
  const Eigen::Vector3d velocity = (target.translation() - now.translation()) / dt;
  Eigen::Vector3d impulse =
      options_.palm_mass_kg * (velocity - from_bullet(palm.getLinearVelocity()));
  if (impulse.norm() > options_.hand_force_n * dt)
    impulse *= options_.hand_force_n * dt / impulse.norm();
  palm.applyCentralImpulse(to_bullet(impulse));
  const Eigen::AngleAxisd error(target.linear() * now.linear().transpose());
  const Eigen::Vector3d spin = error.axis() * error.angle() / dt;
  const btVector3 wanted = to_bullet(spin) - palm.getAngularVelocity();
  const btMatrix3x3 inertia = palm.getInvInertiaTensorWorld().inverse();
  Eigen::Vector3d torque_impulse = from_bullet(inertia * wanted);
  if (torque_impulse.norm() > options_.hand_torque_nm * dt)
    torque_impulse *= options_.hand_torque_nm * dt / torque_impulse.norm();
  palm.applyTorqueImpulse(to_bullet(torque_impulse));
}

void Gripper::drive_fingers(double velocity_m_s) {
  for (auto* slider : sliders_) slider->setTargetLinMotorVelocity(btScalar(velocity_m_s));
}

double Gripper::aperture_m() const {
  const Eigen::Vector3d a = world_.pose(fingers_[0]).translation();
  const Eigen::Vector3d b = world_.pose(fingers_[1]).translation();
  return (b - a).dot(X_BaseHand_.linear().col(1)) - options_.geometry.finger_width_m;
}

std::set<int> Gripper::touching(double tolerance_m) const {
  std::set<int> found;
  for (int part : {palm_, fingers_[0], fingers_[1]})
    for (int id : world_.touching(part, tolerance_m))
      if (id >= 0 && world_.has(id) && world_.role(id) != BodyRole::kGripper) found.insert(id);
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
