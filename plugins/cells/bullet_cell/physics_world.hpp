#pragma once
// One Bullet world (Bullet is not thread-safe across a shared world: one per cell instance).
// Bodies are named by integer ids that stay valid until removed. The world is Bullet's
// multibody world, so articulated bodies (the gripper, Featherstone's reduced coordinates)
// live beside the rigid ones.

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "object_model.hpp"

class btRigidBody;
class btCollisionObject;
class btCollisionShape;
class btMultiBodyDynamicsWorld;

namespace antipode::cells {

struct PhysicsOptions {
  double time_step_s = 1.0 / 240.0;  ///< VGN/GIGA step at 240 Hz
  int solver_iterations = 50;
  double margin_m = 0.001;  ///< convex margin; Bullet's 0.04 m default would float objects
};

enum class BodyRole { kFixture, kObject, kGripper };

/// A world saved between attempts: what each body is (its recipe), where it is and how it
/// moves, and the clock. PhysicsWorld::restore() rebuilds Bullet's world from it.
struct PhysicsSnapshot {
  struct Body {
    int id = -1;
    BodyRole role = BodyRole::kFixture;
    std::string name;
    std::shared_ptr<const ObjectModel> model;  ///< an object's; null for a fixture box
    Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();  ///< a fixture box's
    double friction = 0.0;                                     ///< a fixture box's
    std::shared_ptr<const TriangleMesh> visual;                ///< null: not rendered
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
    Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero();
    int activation = 1;           ///< Bullet's activation state (active, sleeping, ...)
    double deactivation_s = 0.0;  ///< how long the body has been slow enough to sleep
  };
  std::vector<Body> bodies;
  int next_id = 0;
  long steps = 0;
};

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const PhysicsOptions& options);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  /// A static box named `name` (the table, a box wall), rendered unless `visible` is false.
  int add_fixture_box(const std::string& name, const Eigen::Isometry3d& pose,
                      const Eigen::Vector3d& half_extents_m, double friction, bool visible = true);
  int add_object(const ObjectModel& model, const Eigen::Isometry3d& pose);
  void remove_body(int id);

  /// The world now. Throws antipode::Error while a registered part (the gripper) is in it:
  /// a snapshot is taken between attempts.
  PhysicsSnapshot snapshot() const;
  /// Replaces the world with a fresh Bullet world holding the snapshot's bodies, ids, poses,
  /// velocities and clock. Bullet's caches (contact manifolds, solver warm starts) start
  /// empty, so every restore of one snapshot steps identically. Throws antipode::Error while
  /// a registered part is in the world.
  void restore(const PhysicsSnapshot& snapshot);

  /// The Bullet world itself, for parts that manage their own Bullet objects (the gripper
  /// adds its multibody and constraints here and removes them before it is destroyed).
  btMultiBodyDynamicsWorld& dynamics();
  /// Gives `object` (owned by the caller and already in dynamics()) an id, a role and a
  /// name, so that contact queries report it; unregister_part() before it is destroyed.
  int register_part(btCollisionObject* object, BodyRole role, const std::string& name);
  void unregister_part(int id);

  /// The rigid body `id`; throws antipode::Error for an unknown id or a registered part.
  btRigidBody& body(int id) const;
  BodyRole role(int id) const;
  bool has(int id) const { return bodies_.count(id) != 0; }
  std::vector<int> ids(BodyRole role) const;
  const std::string& name(int id) const;

  Eigen::Isometry3d pose(int id) const;

  void step(int steps = 1);
  /// Runs `hook` before every physics step (a controller's drive); an empty one removes it.
  void set_before_step(std::function<void()> hook) { before_step_ = std::move(hook); }
  /// Steps until every object moves slower than `speed_m_s` (or `max_s` has passed).
  void settle(double max_s, double speed_m_s = 0.005);
  double time_s() const { return steps_ * options_.time_step_s; }
  const PhysicsOptions& options() const { return options_; }

  /// Pairs of body ids in contact (distance below `tolerance_m`) after the last step.
  std::set<std::pair<int, int>> contacts(double tolerance_m = 0.0) const;
  /// Ids of bodies touching body `id` now (a fresh collision query, no stepping).
  std::set<int> touching(int id, double tolerance_m = 0.0) const;
  /// Ids of bodies overlapping the box of half extents `half_extents_m` at `pose` now (a
  /// fresh collision query; the box is not part of the world).
  std::set<int> overlapping(const Eigen::Isometry3d& pose,
                            const Eigen::Vector3d& half_extents_m) const;
  /// The same for any Bullet shape (not part of the world) at `pose`.
  std::set<int> overlapping(const Eigen::Isometry3d& pose, btCollisionShape& shape) const;
  /// The deepest interpenetration (m, >= 0) between any two bodies after the last step.
  double deepest_penetration() const;

  /// What the renderer draws: a mesh and its pose per visible body.
  struct Visual {
    std::shared_ptr<const TriangleMesh> mesh;
    Eigen::Isometry3d pose;
  };
  std::vector<Visual> visuals() const;
  /// The mesh drawn for body `id` (in its body frame), null when it is not rendered.
  std::shared_ptr<const TriangleMesh> visual(int id) const;

 private:
  struct Entry;
  int insert(std::unique_ptr<Entry> entry);
  void insert_as(int id, std::unique_ptr<Entry> entry);
  void require_no_parts(const char* what) const;

  PhysicsOptions options_;
  struct Engine;
  std::unique_ptr<Engine> engine_;
  const btCollisionObject& object(int id) const;

  std::map<int, std::unique_ptr<Entry>> bodies_;
  std::function<void()> before_step_;
  int next_id_ = 0;
  long steps_ = 0;
};

}  // namespace antipode::cells
