#include "physics_world.hpp"

#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <algorithm>

#include "antipode/core/error.hpp"
#include "bullet_convert.hpp"
#include "collision_shape.hpp"
#include "primitive_meshes.hpp"

namespace antipode::cells {

struct PhysicsWorld::Engine {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
};

struct PhysicsWorld::Entry {
  BodyRole role = BodyRole::kFixture;
  std::string name;
  ShapeHolder shape;
  std::unique_ptr<btDefaultMotionState> motion;
  std::unique_ptr<btRigidBody> body;           // null for a registered part
  btCollisionObject* object = nullptr;         // the body, or the registered part
  std::shared_ptr<const TriangleMesh> visual;  // null = not rendered
  // The recipe restore() rebuilds it from: an object's model, or a fixture box's size.
  std::shared_ptr<const ObjectModel> model;
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  double friction = 0.0;
};

namespace {

std::unique_ptr<btRigidBody> make_body(ShapeHolder& shape, btDefaultMotionState* motion,
                                       double mass_kg, double friction) {
  btVector3 inertia(0, 0, 0);
  if (mass_kg > 0.0) shape.root->calculateLocalInertia(btScalar(mass_kg), inertia);
  btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass_kg), motion, shape.root.get(),
                                                inertia);
  info.m_friction = btScalar(friction);
  info.m_restitution = 0.0f;
  auto body = std::make_unique<btRigidBody>(info);
  body->setRollingFriction(0.0005f);
  body->setSpinningFriction(0.0005f);
  return body;
}

// The id stored in a body's user index, -1 for bodies this world did not create.
int id_of(const btCollisionObject* object) { return object->getUserIndex(); }

}  // namespace

PhysicsWorld::PhysicsWorld(const PhysicsOptions& options)
    : options_(options), engine_(std::make_unique<Engine>()) {
  engine_->world.setGravity(btVector3(0, 0, -9.81f));
  engine_->world.getSolverInfo().m_numIterations = options.solver_iterations;
}

PhysicsWorld::~PhysicsWorld() {
  for (auto& [id, entry] : bodies_)
    if (entry->body) engine_->world.removeRigidBody(entry->body.get());
}

int PhysicsWorld::insert(std::unique_ptr<Entry> entry) {
  const int id = next_id_++;
  insert_as(id, std::move(entry));
  return id;
}

void PhysicsWorld::insert_as(int id, std::unique_ptr<Entry> entry) {
  entry->object = entry->body.get();
  entry->body->setUserIndex(id);
  engine_->world.addRigidBody(entry->body.get());
  bodies_[id] = std::move(entry);
}

btMultiBodyDynamicsWorld& PhysicsWorld::dynamics() { return engine_->world; }

int PhysicsWorld::register_part(btCollisionObject* object, BodyRole role, const std::string& name) {
  auto entry = std::make_unique<Entry>();
  entry->role = role;
  entry->name = name;
  entry->object = object;
  const int id = next_id_++;
  object->setUserIndex(id);
  bodies_[id] = std::move(entry);
  return id;
}

void PhysicsWorld::unregister_part(int id) {
  auto it = bodies_.find(id);
  if (it != bodies_.end() && !it->second->body) bodies_.erase(it);
}

int PhysicsWorld::add_fixture_box(const std::string& name, const Eigen::Isometry3d& pose,
                                  const Eigen::Vector3d& half, double friction, bool visible) {
  auto entry = std::make_unique<Entry>();
  entry->name = name;
  entry->shape = make_box_shape(half, options_.margin_m);
  entry->motion = std::make_unique<btDefaultMotionState>(to_bullet(pose));
  entry->body = make_body(entry->shape, entry->motion.get(), 0.0, friction);
  if (visible) entry->visual = std::make_shared<const TriangleMesh>(box_mesh(half.cast<float>()));
  entry->half_extents_m = half;
  entry->friction = friction;
  return insert(std::move(entry));
}

int PhysicsWorld::add_object(const ObjectModel& model, const Eigen::Isometry3d& pose) {
  auto entry = std::make_unique<Entry>();
  entry->role = BodyRole::kObject;
  entry->name = model.name;
  entry->shape = make_collision_shape(model.collision, options_.margin_m);
  entry->motion = std::make_unique<btDefaultMotionState>(to_bullet(pose));
  entry->body = make_body(entry->shape, entry->motion.get(), model.mass_kg, model.friction);
  entry->visual = model.visual;
  entry->model = std::make_shared<const ObjectModel>(model);
  return insert(std::move(entry));
}

void PhysicsWorld::remove_body(int id) {
  auto it = bodies_.find(id);
  if (it == bodies_.end() || !it->second->body) return;
  engine_->world.removeRigidBody(it->second->body.get());
  bodies_.erase(it);
}

void PhysicsWorld::require_no_parts(const char* what) const {
  for (const auto& [id, entry] : bodies_)
    if (!entry->body)
      throw Error(std::string("cannot ") + what + " the world while '" + entry->name +
                  "' (a registered part) is in it");
}

PhysicsSnapshot PhysicsWorld::snapshot() const {
  require_no_parts("save");
  PhysicsSnapshot saved;
  saved.next_id = next_id_;
  saved.steps = steps_;
  for (const auto& [id, entry] : bodies_) {
    const btRigidBody& b = *entry->body;
    PhysicsSnapshot::Body body;
    body.id = id;
    body.role = entry->role;
    body.name = entry->name;
    body.model = entry->model;
    body.half_extents_m = entry->half_extents_m;
    body.friction = entry->friction;
    body.visual = entry->visual;
    body.pose = from_bullet(b.getWorldTransform());
    body.velocity_m_s = from_bullet(b.getLinearVelocity());
    body.angular_velocity_rad_s = from_bullet(b.getAngularVelocity());
    body.activation = b.getActivationState();
    body.deactivation_s = b.getDeactivationTime();
    saved.bodies.push_back(std::move(body));
  }
  return saved;
}

void PhysicsWorld::restore(const PhysicsSnapshot& saved) {
  require_no_parts("restore");
  for (auto& [id, entry] : bodies_) engine_->world.removeRigidBody(entry->body.get());
  bodies_.clear();
  engine_ = std::make_unique<Engine>();  // no contact manifold or warm start survives
  engine_->world.setGravity(btVector3(0, 0, -9.81f));
  engine_->world.getSolverInfo().m_numIterations = options_.solver_iterations;
  for (const PhysicsSnapshot::Body& body : saved.bodies) {
    auto entry = std::make_unique<Entry>();
    entry->role = body.role;
    entry->name = body.name;
    entry->model = body.model;
    entry->half_extents_m = body.half_extents_m;
    entry->friction = body.friction;
    const bool object = body.model != nullptr;
    entry->shape = object ? make_collision_shape(body.model->collision, options_.margin_m)
                          : make_box_shape(body.half_extents_m, options_.margin_m);
    entry->motion = std::make_unique<btDefaultMotionState>(to_bullet(body.pose));
    entry->body = make_body(entry->shape, entry->motion.get(), object ? body.model->mass_kg : 0.0,
                            object ? body.model->friction : body.friction);
    entry->visual = body.visual;
    entry->body->setLinearVelocity(to_bullet(body.velocity_m_s));
    entry->body->setAngularVelocity(to_bullet(body.angular_velocity_rad_s));
    insert_as(body.id, std::move(entry));
    btRigidBody& b = *bodies_[body.id]->body;
    b.forceActivationState(body.activation);
    b.setDeactivationTime(btScalar(body.deactivation_s));
  }
  next_id_ = saved.next_id;
  steps_ = saved.steps;
}

btRigidBody& PhysicsWorld::body(int id) const {
  auto it = bodies_.find(id);
  if (it == bodies_.end() || !it->second->body)
    throw Error("physics body " + std::to_string(id) + " does not exist");
  return *it->second->body;
}

const btCollisionObject& PhysicsWorld::object(int id) const {
  auto it = bodies_.find(id);
  if (it == bodies_.end()) throw Error("physics body " + std::to_string(id) + " does not exist");
  return *it->second->object;
}

BodyRole PhysicsWorld::role(int id) const { return bodies_.at(id)->role; }
const std::string& PhysicsWorld::name(int id) const { return bodies_.at(id)->name; }

std::shared_ptr<const TriangleMesh> PhysicsWorld::visual(int id) const {
  return bodies_.at(id)->visual;
}

std::vector<int> PhysicsWorld::ids(BodyRole role) const {
  std::vector<int> out;
  for (const auto& [id, entry] : bodies_)
    if (entry->role == role) out.push_back(id);
  return out;
}

Eigen::Isometry3d PhysicsWorld::pose(int id) const {
  return from_bullet(object(id).getWorldTransform());
}

void PhysicsWorld::step(int steps) {
  const btScalar dt = btScalar(options_.time_step_s);
  for (int i = 0; i < steps; ++i) {
    if (before_step_) before_step_();
    engine_->world.stepSimulation(dt, 0, dt);
  }
  steps_ += steps;
}

void PhysicsWorld::settle(double max_s, double speed_m_s) {
  const int check_every = 12;
  for (double t = 0.0; t < max_s; t += check_every * options_.time_step_s) {
    step(check_every);
    bool resting = true;
    for (int id : ids(BodyRole::kObject)) {
      const btRigidBody& b = body(id);
      if (b.getLinearVelocity().length() > speed_m_s ||
          b.getAngularVelocity().length() > 20.0 * speed_m_s)
        resting = false;
    }
    if (resting) return;
  }
}

std::set<std::pair<int, int>> PhysicsWorld::contacts(double tolerance_m) const {
  std::set<std::pair<int, int>> pairs;
  btDispatcher* dispatcher = engine_->world.getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int c = 0; c < manifold->getNumContacts(); ++c) {
      if (manifold->getContactPoint(c).getDistance() > tolerance_m) continue;
      const int a = id_of(manifold->getBody0()), b = id_of(manifold->getBody1());
      pairs.emplace(std::min(a, b), std::max(a, b));
      break;
    }
  }
  return pairs;
}

namespace {

// Collects the ids of the bodies a contact test finds within `tolerance` of its object.
struct ContactCollector : btCollisionWorld::ContactResultCallback {
  explicit ContactCollector(double tolerance_m) : tolerance(tolerance_m) {
    m_closestDistanceThreshold = btScalar(std::max(0.0, tolerance_m));
  }
  btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* a, int, int,
                           const btCollisionObjectWrapper* b, int, int) override {
    if (point.getDistance() <= tolerance) {
      found.insert(id_of(a->getCollisionObject()));
      found.insert(id_of(b->getCollisionObject()));
    }
    return 0;
  }
  double tolerance;
  std::set<int> found;
};

}  // namespace

std::set<int> PhysicsWorld::touching(int id, double tolerance_m) const {
  ContactCollector collector(tolerance_m);
  engine_->world.contactTest(const_cast<btCollisionObject*>(&object(id)), collector);
  collector.found.erase(id);
  return collector.found;
}

std::set<int> PhysicsWorld::overlapping(const Eigen::Isometry3d& pose,
                                        const Eigen::Vector3d& half_extents_m) const {
  btBoxShape box(to_bullet(half_extents_m));
  box.setMargin(0.0f);
  return overlapping(pose, box);
}

std::set<int> PhysicsWorld::overlapping(const Eigen::Isometry3d& pose,
                                        btCollisionShape& shape) const {
  btCollisionObject probe;
  probe.setCollisionShape(&shape);
  probe.setWorldTransform(to_bullet(pose));
  probe.setUserIndex(-1);
  ContactCollector collector(0.0);
  engine_->world.contactTest(&probe, collector);
  collector.found.erase(-1);
  return collector.found;
}

double PhysicsWorld::deepest_penetration() const {
  double deepest = 0.0;
  btDispatcher* dispatcher = engine_->world.getDispatcher();
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    for (int c = 0; c < manifold->getNumContacts(); ++c)
      deepest = std::max(deepest, -double(manifold->getContactPoint(c).getDistance()));
  }
  return deepest;
}

std::vector<PhysicsWorld::Visual> PhysicsWorld::visuals() const {
  std::vector<Visual> out;
  for (const auto& [id, entry] : bodies_)
    if (entry->visual) out.push_back({entry->visual, pose(id)});
  return out;
}

}  // namespace antipode::cells
