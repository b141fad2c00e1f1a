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
// The shapes are placed at X_BaseShapeA and X_BaseShapeB.
bool collide(const Shape& a, const Eigen::Isometry3d& X_BaseShapeA, const Shape& b,
             const Eigen::Isometry3d& X_BaseShapeB) {
  const double reach = a.radius_m + b.radius_m;
  if (std::isfinite(reach) &&
      (X_BaseShapeA.translation() - X_BaseShapeB.translation()).squaredNorm() > reach * reach) {
    return false;
  }
  const fcl::CollisionObjectd oa(a.geometry, X_BaseShapeA);
  const fcl::CollisionObjectd ob(b.geometry, X_BaseShapeB);
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
  // A robot link with shapes. A moving link hangs from the arm chain's link `arm_link` (an
  // index into the chain's link_names()) by the constant X_ParentLink (joints off the arm
  // keep their values); a fixed one stands at X_ParentLink in the base frame.
  struct Link {
    std::string name;
    std::vector<Shape> shapes;
    std::size_t first_shape = 0;  // where its shapes' poses start in check()'s array
    bool moving = false;
    std::size_t arm_link = 0;
    Eigen::Isometry3d X_ParentLink = Eigen::Isometry3d::Identity();
  };
  struct Box {
    std::string name;
    Shape shape;
  };

  KinematicChain arm;
  std::vector<Link> links;
  std::size_t shape_count = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // indices into links
  std::vector<Box> boxes;
  Shape points;                        // geometry null when there are none
  std::vector<char> points_unchecked;  // per link

  // Every shape's pose with the arm's links at `arm` (KinematicChain::link_poses), link by
  // link from each link's first_shape.
  std::vector<Eigen::Isometry3d> shape_poses(const std::vector<Eigen::Isometry3d>& arm) const {
    std::vector<Eigen::Isometry3d> poses;
    poses.reserve(shape_count);
    for (const Link& link : links) {
      const Eigen::Isometry3d X_BaseLink =
          link.moving ? arm[link.arm_link] * link.X_ParentLink : link.X_ParentLink;
      for (const Shape& shape : link.shapes) poses.push_back(X_BaseLink * shape.X_LinkShape);
    }
    return poses;
  }

  bool links_collide(std::size_t a, std::size_t b,
                     const std::vector<Eigen::Isometry3d>& poses) const {
    const Link& la = links[a];
    const Link& lb = links[b];
    for (std::size_t i = 0; i < la.shapes.size(); ++i)
      for (std::size_t j = 0; j < lb.shapes.size(); ++j)
        if (collide(la.shapes[i], poses[la.first_shape + i], lb.shapes[j],
                    poses[lb.first_shape + j]))
          return true;
    return false;
  }
};

namespace {

// The link `name` of `robot` for the world of `arm`: whether it moves with the arm, and its
// pose relative to the arm link it hangs from (or to the base), from its own chain with the
// arm at `q_arm` and every other joint at its value in `joint_values` (0 if absent).
ArmCollisionWorld::Impl::Link make_link(const RobotModel& robot, const KinematicChain& arm,
                                        const std::string& name,
                                        const std::map<std::string, double>& joint_values,
                                        const Eigen::VectorXd& q_arm,
                                        const std::vector<Eigen::Isometry3d>& arm_poses) {
  ArmCollisionWorld::Impl::Link link;
  link.name = name;
  const KinematicChain chain = robot.chain(arm.base_link(), name);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.dof()));
  for (std::size_t j = 0; j < chain.dof(); ++j) {
    const std::string& joint = chain.joint_names()[j];
    const auto& arm_joints = arm.joint_names();
    const auto in_arm = std::find(arm_joints.begin(), arm_joints.end(), joint);
    if (in_arm != arm_joints.end()) {
      link.moving = true;
      q(Eigen::Index(j)) = q_arm(in_arm - arm_joints.begin());
    } else if (const auto fixed = joint_values.find(joint); fixed != joint_values.end()) {
      q(Eigen::Index(j)) = fixed->second;
    }
  }
  link.X_ParentLink = chain.forward(q);
  if (link.moving) {
    // The deepest arm-chain link on this link's path from the base.
    const std::vector<std::string> path = chain.link_names();
    const std::vector<std::string> arm_links = arm.link_names();
    for (std::size_t k = 0; k < arm_links.size(); ++k)
      if (std::find(path.begin(), path.end(), arm_links[k]) != path.end()) link.arm_link = k;
    link.X_ParentLink = arm_poses[link.arm_link].inverse() * link.X_ParentLink;
  }
  for (const CollisionPrimitive& p : robot.collision_shapes(name))
    link.shapes.push_back(make_shape(p));
  return link;
}

}  // namespace

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
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(arm.dof()));
  for (std::size_t j = 0; j < arm.dof(); ++j)
    zero(Eigen::Index(j)) = std::clamp(0.0, arm.limits()[j].lower, arm.limits()[j].upper);
  const std::vector<Eigen::Isometry3d> arm_at_zero = arm.link_poses(zero);
  for (const std::string& name : robot.link_names()) {
    if (robot.collision_shapes(name).empty()) continue;
    impl_->links.push_back(make_link(robot, arm, name, joint_values, zero, arm_at_zero));
    impl_->links.back().first_shape = impl_->shape_count;
    impl_->shape_count += impl_->links.back().shapes.size();
  }
  // Self-collision pairs: an arm link with any other link, unless within
  // kMinJointsApart moving joints of it (collision_pairs.hpp) or in contact at the arm's zero
  // configuration (clamped into the limits).
  const auto& links = impl_->links;
  const std::vector<Eigen::Isometry3d> at_zero = impl_->shape_poses(arm_at_zero);
  for (std::size_t a = 0; a < links.size(); ++a) {
    for (std::size_t b = a + 1; b < links.size(); ++b) {
      if (!links[a].moving && !links[b].moving) continue;
      if (moving_joints_between(robot, links[a].name, links[b].name) < kMinJointsApart) continue;
      if (!impl_->links_collide(a, b, at_zero)) impl_->pairs.emplace_back(a, b);
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
                                   double resolution_m,
                                   const std::vector<std::string>& unchecked_links) {
  if (!(resolution_m >= 0.001 && resolution_m <= 1.0))
    throw Error("collision world: octree resolution must be in [0.001, 1] m, got " +
                std::to_string(resolution_m));
  std::vector<char> unchecked(impl_->links.size(), 0);
  for (const std::string& name : unchecked_links) {
    const auto it = std::find_if(impl_->links.begin(), impl_->links.end(),
                                 [&](const Impl::Link& l) { return l.name == name; });
    if (it == impl_->links.end())
      throw Error("collision world: no link with collision shapes named '" + name + "'");
    unchecked[std::size_t(it - impl_->links.begin())] = 1;
  }
  impl_->points_unchecked = std::move(unchecked);
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
  const std::vector<Eigen::Isometry3d> poses = impl_->shape_poses(impl_->arm.link_poses(q));
  for (const auto& [a, b] : impl_->pairs) {
    if (impl_->links_collide(a, b, poses)) {
      const bool a_moves = links[a].moving;
      return {ContactReport::Kind::kSelf, a_moves ? links[a].name : links[b].name,
              a_moves ? links[b].name : links[a].name};
    }
  }
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (!links[i].moving) continue;
    const bool check_points = impl_->points.geometry && !impl_->points_unchecked[i];
    for (std::size_t k = 0; k < links[i].shapes.size(); ++k) {
      const Shape& s = links[i].shapes[k];
      const Eigen::Isometry3d& X_BaseShape = poses[links[i].first_shape + k];
      for (const Impl::Box& box : impl_->boxes)
        if (collide(s, X_BaseShape, box.shape, box.shape.X_LinkShape))
          return {ContactReport::Kind::kEnvironment, links[i].name, box.name};
      if (check_points && collide(s, X_BaseShape, impl_->points, identity))
        return {ContactReport::Kind::kEnvironment, links[i].name, "points"};
    }
  }
  return {};
}

std::vector<std::pair<std::string, std::string>> ArmCollisionWorld::self_pairs() const {
  std::vector<std::pair<std::string, std::string>> names;
  for (const auto& [a, b] : impl_->pairs)
    names.emplace_back(impl_->links[a].name, impl_->links[b].name);
  return names;
}
std::vector<std::string> ArmCollisionWorld::arm_links() const {
  std::vector<std::string> names;
  for (const auto& link : impl_->links)
    if (link.moving) names.push_back(link.name);
  return names;
}

}  // namespace antipode::collision
