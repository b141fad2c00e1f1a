#include "arm_collision_world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include <fcl/geometry/octree/octree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <octomap/OcTree.h>

#include "antipode/core/error.hpp"
#include "collision_pairs.hpp"

namespace antipode::collision {

namespace {

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

// Self-collision is checked between links three or more moving joints apart.
constexpr int kMinJointsApart = 3;

Geometry make_geometry(const CollisionPrimitive& p) {
  switch (p.kind) {
    case CollisionPrimitive::Kind::kBox:
      return std::make_shared<fcl::Boxd>(p.size_m.x(), p.size_m.y(), p.size_m.z());
    case CollisionPrimitive::Kind::kCylinder:
      return std::make_shared<fcl::Cylinderd>(p.size_m.x(), p.size_m.y());
    case CollisionPrimitive::Kind::kSphere:
      return std::make_shared<fcl::Sphered>(p.size_m.x());
  }
  return nullptr;
}

// The radius of the smallest sphere about a primitive's centre that holds it.
double bounding_radius(const CollisionPrimitive& p) {
  switch (p.kind) {
    case CollisionPrimitive::Kind::kBox:
      return 0.5 * p.size_m.norm();
    case CollisionPrimitive::Kind::kCylinder:
      return std::hypot(p.size_m.x(), 0.5 * p.size_m.y());
    case CollisionPrimitive::Kind::kSphere:
      return p.size_m.x();
  }
  return 0.0;
}

// One shape of a link (or of the scene), with its bounding sphere about X_LinkShape's origin
// (infinite for the points' octree).
struct Shape {
  Geometry geometry;
  Eigen::Isometry3d X_LinkShape = Eigen::Isometry3d::Identity();
  double radius_m = std::numeric_limits<double>::infinity();
};

Shape make_shape(const CollisionPrimitive& p) {
  return {make_geometry(p), p.X_LinkShape, bounding_radius(p)};
}

// FCL's exact test, after the bounding spheres: most pairs of a robot's links are far apart,
// and the sphere test costs a few nanoseconds where FCL's costs a few hundred.
bool collide(const Shape& a, const Eigen::Isometry3d& X_BaseA, const Shape& b,
             const Eigen::Isometry3d& X_BaseB) {
  const Eigen::Isometry3d X_BaseShapeA = X_BaseA * a.X_LinkShape;
  const Eigen::Isometry3d X_BaseShapeB = X_BaseB * b.X_LinkShape;
  const double reach = a.radius_m + b.radius_m;
  if (std::isfinite(reach) &&
      (X_BaseShapeA.translation() - X_BaseShapeB.translation()).squaredNorm() > reach * reach) {
    return false;
  }
  const fcl::CollisionObjectd oa(a.geometry, X_BaseA * a.X_LinkShape);
  const fcl::CollisionObjectd ob(b.geometry, X_BaseB * b.X_LinkShape);
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&oa, &ob, request, result);
  return result.isCollision();
}

}  // namespace

std::string ContactReport::str() const {
  switch (kind) {
    case Kind::kFree:
      return "free";
    case Kind::kSelf:
      return "self-collision: " + link + " with " + other;
    case Kind::kEnvironment:
      return "collision: " + link + " with " + other;
  }
  return "";
}

struct ArmCollisionWorld::Impl {
  // A robot link with shapes: its chain from the base and where each chain joint's value
  // comes from (an index into the arm's q, or -1 for its fixed value).
  struct Link {
    std::string name;
    KinematicChain chain;
    std::vector<int> arm_index;
    Eigen::VectorXd fixed_q;
    std::vector<Shape> shapes;
    bool moving = false;
    Eigen::Isometry3d X_BaseLink = Eigen::Isometry3d::Identity();  // when not moving
  };
  struct Box {
    std::string name;
    Shape shape;
  };

  KinematicChain arm;
  std::vector<Link> links;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // indices into links
  std::vector<std::pair<std::string, std::string>> pair_names;
  std::vector<Box> boxes;
  Shape points;  // geometry null when there are none

  Eigen::Isometry3d pose(const Link& link, const Eigen::VectorXd& q) const {
    if (!link.moving) return link.X_BaseLink;
    Eigen::VectorXd ql = link.fixed_q;
    for (Eigen::Index i = 0; i < ql.size(); ++i)
      if (link.arm_index[std::size_t(i)] >= 0) ql(i) = q(link.arm_index[std::size_t(i)]);
    return link.chain.forward(ql);
  }

  bool links_collide(const Link& a, const Eigen::Isometry3d& xa, const Link& b,
                     const Eigen::Isometry3d& xb) const {
    for (const Shape& sa : a.shapes)
      for (const Shape& sb : b.shapes)
        if (collide(sa, xa, sb, xb)) return true;
    return false;
  }
};

ArmCollisionWorld::ArmCollisionWorld(const RobotModel& robot, const KinematicChain& arm,
                                     const std::map<std::string, double>& joint_values)
    : impl_(std::make_unique<Impl>()) {
  if (arm.base_link() != robot.root_link()) {
    throw Error("collision world: the arm chain must start at the robot's root link '" +
                robot.root_link() + "', not '" + arm.base_link() + "'");
  }
  const std::vector<std::string> joints = robot.joint_names();
  for (const auto& entry : joint_values) {
    if (!std::binary_search(joints.begin(), joints.end(), entry.first))
      throw Error("collision world: no joint '" + entry.first + "'" +
                  did_you_mean(entry.first, joints));
  }
  impl_->arm = arm;
  for (const std::string& name : robot.link_names()) {
    const std::vector<CollisionPrimitive> primitives = robot.collision_shapes(name);
    if (primitives.empty()) continue;
    Impl::Link link;
    link.name = name;
    link.chain = robot.chain(arm.base_link(), name);
    link.fixed_q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(link.chain.dof()));
    for (std::size_t j = 0; j < link.chain.dof(); ++j) {
      const std::string& joint = link.chain.joint_names()[j];
      const auto in_arm = std::find(arm.joint_names().begin(), arm.joint_names().end(), joint);
      const bool moves = in_arm != arm.joint_names().end();
      link.arm_index.push_back(moves ? int(in_arm - arm.joint_names().begin()) : -1);
      link.moving = link.moving || moves;
      const auto fixed = joint_values.find(joint);
      if (fixed != joint_values.end()) link.fixed_q(Eigen::Index(j)) = fixed->second;
    }
    for (const CollisionPrimitive& p : primitives) link.shapes.push_back(make_shape(p));
    if (!link.moving) link.X_BaseLink = link.chain.forward(link.fixed_q);
    impl_->links.push_back(std::move(link));
  }
  // Self-collision pairs: an arm link with any other link, unless within
  // kMinJointsApart moving joints of it (collision_pairs.hpp) or in contact at the arm's zero
  // configuration (clamped into the limits).
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(arm.dof()));
  for (std::size_t j = 0; j < arm.dof(); ++j)
    zero(Eigen::Index(j)) = std::clamp(0.0, arm.limits()[j].lower, arm.limits()[j].upper);
  const auto& links = impl_->links;
  for (std::size_t a = 0; a < links.size(); ++a) {
    for (std::size_t b = a + 1; b < links.size(); ++b) {
      if (!links[a].moving && !links[b].moving) continue;
      if (moving_joints_between(robot, links[a].name, links[b].name) < kMinJointsApart) continue;
      if (impl_->links_collide(links[a], impl_->pose(links[a], zero), links[b],
                               impl_->pose(links[b], zero))) {
        continue;
      }
      impl_->pairs.emplace_back(a, b);
      impl_->pair_names.emplace_back(links[a].name, links[b].name);
    }
  }
}

ArmCollisionWorld::~ArmCollisionWorld() = default;
ArmCollisionWorld::ArmCollisionWorld(ArmCollisionWorld&&) noexcept = default;
ArmCollisionWorld& ArmCollisionWorld::operator=(ArmCollisionWorld&&) noexcept = default;

void ArmCollisionWorld::add_box(const std::string& name, const Eigen::Isometry3d& X_BaseBox,
                                const Eigen::Vector3d& size_m) {
  if (!(size_m.array() > 0.0).all() || !size_m.allFinite())
    throw Error("collision world: box '" + name + "' needs positive sizes");
  CollisionPrimitive p;
  p.size_m = size_m;
  p.X_LinkShape = X_BaseBox;
  impl_->boxes.push_back({name, make_shape(p)});
}

void ArmCollisionWorld::set_points(const std::vector<Eigen::Vector3f>& points_m,
                                   double resolution_m) {
  if (!(resolution_m >= 0.001 && resolution_m <= 1.0))
    throw Error("collision world: octree resolution must be in [0.001, 1] m, got " +
                std::to_string(resolution_m));
  impl_->points = {};
  if (points_m.empty()) return;
  auto tree = std::make_shared<octomap::OcTree>(resolution_m);
  for (const Eigen::Vector3f& p : points_m)
    if (p.allFinite()) tree->updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  impl_->points.geometry =
      std::make_shared<fcl::OcTreed>(std::shared_ptr<const octomap::OcTree>(tree));
}

ContactReport ArmCollisionWorld::check(const Eigen::VectorXd& q) const {
  if (static_cast<std::size_t>(q.size()) != impl_->arm.dof() || !q.allFinite()) {
    throw Error("collision check: " + std::to_string(q.size()) + " joint values for the " +
                std::to_string(impl_->arm.dof()) + " joints of the arm (all finite)");
  }
  const auto& links = impl_->links;
  std::vector<Eigen::Isometry3d> poses(links.size());
  for (std::size_t i = 0; i < links.size(); ++i) poses[i] = impl_->pose(links[i], q);
  ContactReport report;
  for (const auto& [a, b] : impl_->pairs) {
    if (impl_->links_collide(links[a], poses[a], links[b], poses[b])) {
      const bool a_moves = links[a].moving;
      return {ContactReport::Kind::kSelf, a_moves ? links[a].name : links[b].name,
              a_moves ? links[b].name : links[a].name};
    }
  }
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (!links[i].moving) continue;
    for (const Shape& s : links[i].shapes) {
      for (const Impl::Box& box : impl_->boxes)
        if (collide(s, poses[i], box.shape, identity))
          return {ContactReport::Kind::kEnvironment, links[i].name, box.name};
      if (impl_->points.geometry && collide(s, poses[i], impl_->points, identity))
        return {ContactReport::Kind::kEnvironment, links[i].name, "points"};
    }
  }
  return report;
}

const std::vector<std::pair<std::string, std::string>>& ArmCollisionWorld::self_pairs() const {
  return impl_->pair_names;
}

std::vector<std::string> ArmCollisionWorld::arm_links() const {
  std::vector<std::string> names;
  for (const auto& link : impl_->links)
    if (link.moving) names.push_back(link.name);
  return names;
}

}  // namespace antipode::collision
