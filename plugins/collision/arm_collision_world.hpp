#pragma once
// The collision world of one robot arm: the arm's links (their URDF primitives) against the
// rest of the robot (self-collision) and against the scene - known boxes (table, box walls)
// and the observed points as an octree - checked with FCL.
//
// Frames and units: everything in the robot's base frame, metres; `q` holds the arm chain's
// joint values in radians. Links that do not move with the arm keep the poses of the joint
// values given at construction (every other joint at 0, unless named there).
//
// How: FCL with its exact shapes is the reference (CheckMode::kExact). By default each link
// is first covered by spheres (sphere_arm.hpp), and only the link pairs, link and box, or
// link and points whose spheres touch are tested further - by the primitives' own quick
// tests (primitive_tests.hpp), then FCL where those cannot tell: the same answer as FCL
// alone, since the spheres hold the shapes, in a fraction of the time where most of the arm
// is clear. A batch whose spheres show a contact certain (the balls inside the links meet an
// obstacle) needs neither.
// CheckMode::kSpheres answers from the spheres alone: never free where FCL finds a contact,
// but in contact where the spheres overlap and the shapes are apart (by up to overshoot_m()
// against a box, twice it between two links, and the points' grid margin, sqrt(3) cells,
// more against the points; a cylinder added to the scene counts as its bounding box).
//
// Threads: check() is const and keeps no state between calls (beyond per-thread scratch
// memory); concurrent checks on one world are safe. add_box() and set_points() must not run
// concurrently with anything else.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"
#include "antipode/robot/robot_model.hpp"

namespace antipode::collision {

/// What check() found: no contact, or the first pair in contact.
struct ContactReport {
  enum class Kind { kFree, kSelf, kEnvironment };
  Kind kind = Kind::kFree;
  std::string link;   ///< the arm's link in contact
  std::string other;  ///< the other robot link, the box's name, or "points"

  bool free() const { return kind == Kind::kFree; }
  /// "free", "self-collision: A with B" or "collision: A with B".
  std::string str() const;
};

enum class CheckMode {
  kSpheresThenExact,  ///< spheres first, then quick tests and FCL where they touch: FCL's answer
  kExact,             ///< FCL alone
  kSpheres,           ///< spheres alone: conservative (a contact may be up to the overshoot)
};

struct CollisionOptions {
  CheckMode mode = CheckMode::kSpheresThenExact;
  /// How far the spheres may reach beyond a link's shapes where the cover can keep to it
  /// (sphere_cover.hpp; a fat short cylinder's one sphere reaches farther).
  double sphere_overshoot_m = 0.01;
  /// How set_points builds the points' octree: once per occupied leaf (default), or one
  /// point at a time as octomap inserts them - the same tree, about ten times slower, kept
  /// as the baseline the reach benchmark compares with (points_octree.hpp).
  bool octree_point_by_point = false;
};

class ArmCollisionWorld {
 public:
  /// The arm is `arm` (a chain of `robot`); `joint_values` fixes any other joint by name
  /// (e.g. the other arm, the fingers). Throws antipode::Error for an unknown joint name or
  /// a link with an unsupported shape; antipode::InternalError when the arm's joint axes,
  /// read off the chain, do not reproduce its forward kinematics (screw_chain.hpp, which
  /// places the shapes in every mode).
  ArmCollisionWorld(const RobotModel& robot, const KinematicChain& arm,
                    const std::map<std::string, double>& joint_values = {},
                    const CollisionOptions& options = {});
  ~ArmCollisionWorld();
  ArmCollisionWorld(ArmCollisionWorld&&) noexcept;
  ArmCollisionWorld& operator=(ArmCollisionWorld&&) noexcept;

  /// An obstacle box of `size_m` (full lengths) centred at X_BaseBox. Throws antipode::Error
  /// for a size that is not positive.
  void add_box(const std::string& name, const Eigen::Isometry3d& X_BaseBox,
               const Eigen::Vector3d& size_m);
  /// An obstacle cylinder along the z axis of X_BaseCylinder, centred there (the spheres test
  /// its bounding box; FCL the cylinder). Throws antipode::Error for a size that is not
  /// positive.
  void add_cylinder(const std::string& name, const Eigen::Isometry3d& X_BaseCylinder,
                    double radius_m, double length_m);
  /// The observed points (base frame) as an octree of `resolution_m` cells, replacing any
  /// earlier points; an empty vector removes them. The links named in `unchecked_links` are
  /// not checked against them (e.g. a gripper whose own check against the cloud is finer).
  /// Throws antipode::Error for a resolution outside [0.001, 1] m or an unknown link.
  void set_points(const std::vector<Eigen::Vector3f>& points_m, double resolution_m,
                  const std::vector<std::string>& unchecked_links = {});

  /// The arm at `q` against itself, the fixed robot and the scene: self-collision first,
  /// then the boxes, then the points. Throws antipode::Error unless `q` has one finite value
  /// per arm joint.
  ContactReport check(const Eigen::VectorXd& q) const;

  /// The index of the first of `qs` (in their order) in contact, or qs.size() when every one
  /// is free, with the spheres testing 16 configurations at a time (in kSpheresThenExact mode
  /// FCL confirming, in order, the ones they flag, on the link pairs and the links and
  /// obstacles whose spheres touch there): check()'s answers in kExact and
  /// kSpheresThenExact mode; in kSpheres mode as conservative as check(), though a state at
  /// the edge of a sphere may come out otherwise (the batch computes its sines apart).
  /// Throws like check().
  std::size_t first_contact(const std::vector<Eigen::VectorXd>& qs) const;

  /// The links rigid with the arm's tip (no arm joint between them and it: a gripper's
  /// housing and fingers, with their joints at the values given at construction) placed with
  /// the tip at X_BaseTip, against the boxes and the points, with FCL's exact shapes - no
  /// joint values needed. check(q) finds the same contacts for these links at every q whose
  /// tip is at X_BaseTip, so a hand in contact here rules out every IK solution for it
  /// (check_reach asks this before solving any). Not checked: self-collision, which depends
  /// on q. Thread-safe like check().
  ContactReport check_tip_links(const Eigen::Isometry3d& X_BaseTip) const;
  /// The names of the links check_tip_links() places.
  std::vector<std::string> tip_links() const;

  /// Link pairs checked for self-collision: an arm link with a robot link three or more
  /// moving joints away (collision_pairs.hpp) and not in contact at the arm's zero
  /// configuration.
  std::vector<std::pair<std::string, std::string>> self_pairs() const;
  /// The links that move with the arm.
  std::vector<std::string> arm_links() const;
  /// The spheres covering the robot's links, and the largest distance any of them reaches
  /// beyond its link's shapes (metres).
  std::size_t spheres() const;
  double overshoot_m() const;
  CheckMode mode() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace antipode::collision
