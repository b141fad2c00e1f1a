#include "arm_collision_world.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <utility>

#include <fcl/geometry/octree/octree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/narrowphase/collision.h>
#include <octomap/OcTree.h>

#include "antipode/core/error.hpp"
#include "collision_pairs.hpp"
#include "distance_grid.hpp"
#include "points_octree.hpp"
#include "primitive_tests.hpp"
#include "sphere_arm.hpp"

namespace antipode::collision {

namespace {

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

// A number no other world has had in this process.
std::uint64_t next_id() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

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
// (infinite for the points' octree), and the primitive it is (none for the points' octree).
struct Shape {
  Geometry geometry;
  Eigen::Isometry3d X_LinkShape = Eigen::Isometry3d::Identity();
  double radius_m = std::numeric_limits<double>::infinity();
  std::optional<CollisionPrimitive> primitive;
};

Shape make_shape(const CollisionPrimitive& p) {
  return {make_geometry(p), p.X_LinkShape, bounding_radius(p), p};
}

// FCL's exact test, after the bounding spheres: most pairs of a robot's links are far apart,
// and the sphere test costs a few nanoseconds where FCL's costs a few hundred. With `quick`,
// the primitives' own tests (primitive_tests.hpp) answer first where they can, as FCL would.
// The shapes are placed at X_BaseShapeA and X_BaseShapeB.
bool collide(const Shape& a, const Eigen::Isometry3d& X_BaseShapeA, const Shape& b,
             const Eigen::Isometry3d& X_BaseShapeB, bool quick) {
  const double reach = a.radius_m + b.radius_m;
  if (std::isfinite(reach) &&
      (X_BaseShapeA.translation() - X_BaseShapeB.translation()).squaredNorm() > reach * reach) {
    return false;
  }
  if (quick && a.primitive && b.primitive) {
    const Verdict verdict = quick_test({a.primitive->kind, a.primitive->size_m, X_BaseShapeA},
                                       {b.primitive->kind, b.primitive->size_m, X_BaseShapeB});
    if (verdict != Verdict::kUndecided) return verdict == Verdict::kMeet;
  }
  // The geometries and poses straight to FCL: a CollisionObject would also compute a box
  // around each shape, which the test does not read.
  const fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(a.geometry.get(), X_BaseShapeA, b.geometry.get(), X_BaseShapeB, request, result);
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
    std::vector<CollisionPrimitive> primitives;
    std::vector<Shape> shapes;
    std::size_t first_shape = 0;  // where its shapes' poses start in check()'s array
    bool moving = false;
    std::size_t arm_link = 0;
    Eigen::Isometry3d X_ParentLink = Eigen::Isometry3d::Identity();
    // Below the arm's last joint: rigid with the tip, at X_TipLink from it.
    bool rigid_with_tip = false;
    Eigen::Isometry3d X_TipLink = Eigen::Isometry3d::Identity();
  };
  struct Box {  // an obstacle: a box, or a cylinder (add_cylinder)
    std::string name;
    Shape shape;
  };

  KinematicChain arm;
  std::optional<ScrewChain> fk;  // the arm's links' poses for FCL, in double
  CollisionOptions options;
  std::vector<Link> links;
  std::size_t shape_count = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // indices into links
  // FCL's shape poses: the fixed links' placed once, a moving link's shape at its arm link's
  // pose times a constant.
  std::vector<Eigen::Isometry3d> still_poses, X_ArmLinkShape;
  std::uint64_t id = next_id();  // tells this world's shape poses from another's
  std::vector<Box> boxes;
  Shape points;                        // geometry null when there are none
  std::vector<char> points_unchecked;  // per link
  // The fast path (none in kExact mode): the spheres, the boxes as its kernels take them,
  // the points' distance grid, and the spheres' radii against the points.
  std::unique_ptr<SphereArm> spheres;
  std::vector<KernelBox> kernel_boxes;
  DistanceGrid grid;
  std::vector<float> points_radius;

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

  // Fills still_poses and X_ArmLinkShape from the arm's link poses at any configuration.
  void place_still_shapes(const std::vector<Eigen::Isometry3d>& any_arm_poses) {
    still_poses = shape_poses(any_arm_poses);
    id = next_id();
    X_ArmLinkShape.assign(shape_count, Eigen::Isometry3d::Identity());
    for (const Link& link : links)
      for (std::size_t k = 0; link.moving && k < link.shapes.size(); ++k)
        X_ArmLinkShape[link.first_shape + k] = link.X_ParentLink * link.shapes[k].X_LinkShape;
  }
  // Every shape's pose with the arm at `q`, in a thread-local buffer that the next call on the
  // thread overwrites. The fixed shapes' poses are copied in only when the buffer last held
  // another world's: a confirmation of what the spheres flag places the moving shapes alone.
  const std::vector<Eigen::Isometry3d>& shape_poses_at(const Eigen::VectorXd& q) const {
    thread_local std::vector<Eigen::Isometry3d> arm_poses, poses;
    thread_local std::uint64_t holds = 0;
    if (holds != id) {
      poses = still_poses;
      holds = id;
    }
    arm_poses.resize(fk->links());
    fk->link_poses(q.data(), arm_poses.data());
    for (const Link& link : links)
      for (std::size_t k = 0; link.moving && k < link.shapes.size(); ++k)
        poses[link.first_shape + k] =
            arm_poses[link.arm_link] * X_ArmLinkShape[link.first_shape + k];
    return poses;
  }

  // Whether FCL's tests are preceded by the primitives' own: where the spheres flag a pair.
  // The exact mode, the reference, asks FCL alone.
  bool quick_tests() const { return options.mode == CheckMode::kSpheresThenExact; }

  bool links_collide(std::size_t a, std::size_t b,
                     const std::vector<Eigen::Isometry3d>& poses) const {
    const Link& la = links[a];
    const Link& lb = links[b];
    for (std::size_t i = 0; i < la.shapes.size(); ++i)
      for (std::size_t j = 0; j < lb.shapes.size(); ++j)
        if (collide(la.shapes[i], poses[la.first_shape + i], lb.shapes[j],
                    poses[lb.first_shape + j], quick_tests()))
          return true;
    return false;
  }

  // The first contact of moving link i with the boxes and points that `near` names (bits as
  // SphereArm::environment_contacts()'s), shape by shape, the boxes before the points. With
  // `confirm` false the first named is taken for a contact without FCL.
  template <class Poses>
  std::optional<ContactReport> environment_contact(std::size_t i, std::uint32_t near, bool confirm,
                                                   Poses&& fcl_poses) const {
    const auto box_near = [near](std::size_t b) {
      return (near >> std::min(int(b), SphereArm::kLastBoxBit) & 1U) != 0;
    };
    const bool points_near =
        (near >> SphereArm::kPointsBit & 1U) && points.geometry && !points_unchecked[i];
    const auto contact = [&](const std::string& other) {
      return ContactReport{ContactReport::Kind::kEnvironment, links[i].name, other};
    };
    if (!confirm) {
      for (std::size_t b = 0; b < boxes.size(); ++b)
        if (box_near(b)) return contact(boxes[b].name);
      if (points_near) return contact("points");
      return std::nullopt;
    }
    const std::vector<Eigen::Isometry3d>& poses = fcl_poses();
    const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
    for (std::size_t k = 0; k < links[i].shapes.size(); ++k) {
      const Shape& s = links[i].shapes[k];
      const Eigen::Isometry3d& X_BaseShape = poses[links[i].first_shape + k];
      for (std::size_t b = 0; b < boxes.size(); ++b)
        if (box_near(b) &&
            collide(s, X_BaseShape, boxes[b].shape, boxes[b].shape.X_LinkShape, quick_tests()))
          return contact(boxes[b].name);
      if (points_near && collide(s, X_BaseShape, points, identity, false)) return contact("points");
    }
    return std::nullopt;
  }

  ContactReport self_report(std::size_t pair) const {
    const auto [a, b] = pairs[pair];
    const bool a_moves = links[a].moving;
    return {ContactReport::Kind::kSelf, a_moves ? links[a].name : links[b].name,
            a_moves ? links[b].name : links[a].name};
  }

  ContactReport check_exact(const Eigen::VectorXd& q) const;
  ContactReport check_with_spheres(const Eigen::VectorXd& q) const;
  bool confirm(const Eigen::VectorXd& q, const SphereArm::BatchContacts& touched, int lane) const;
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
    // Every arm joint lies on the path from the base to the tip, so a link below the last one
    // has none between it and the tip.
    const std::vector<std::string>& path_joints = chain.joint_names();
    link.rigid_with_tip = arm.dof() > 0 && std::find(path_joints.begin(), path_joints.end(),
                                                     arm.joint_names().back()) != path_joints.end();
    link.X_TipLink = arm_poses.back().inverse() * arm_poses[link.arm_link] * link.X_ParentLink;
  }
  link.primitives = robot.collision_shapes(name);
  for (const CollisionPrimitive& p : link.primitives) link.shapes.push_back(make_shape(p));
  return link;
}

}  // namespace

ArmCollisionWorld::ArmCollisionWorld(const RobotModel& robot, const KinematicChain& arm,
                                     const std::map<std::string, double>& joint_values,
                                     const CollisionOptions& options)
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
  impl_->fk.emplace(arm);
  impl_->options = options;
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
  impl_->place_still_shapes(arm_at_zero);
  const auto& links = impl_->links;
  const std::vector<Eigen::Isometry3d> at_zero = impl_->shape_poses(arm_at_zero);
  for (std::size_t a = 0; a < links.size(); ++a) {
    for (std::size_t b = a + 1; b < links.size(); ++b) {
      if (!links[a].moving && !links[b].moving) continue;
      if (moving_joints_between(robot, links[a].name, links[b].name) < kMinJointsApart) continue;
      if (!impl_->links_collide(a, b, at_zero)) impl_->pairs.emplace_back(a, b);
    }
  }
  if (options.mode == CheckMode::kExact) return;
  std::vector<SphereArm::Link> sphere_links;
  sphere_links.reserve(links.size());
  for (const Impl::Link& link : links)
    sphere_links.push_back(
        {link.primitives, link.moving ? int(link.arm_link) : -1, link.X_ParentLink});
  impl_->spheres =
      std::make_unique<SphereArm>(arm, sphere_links, impl_->pairs, options.sphere_overshoot_m);
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
  impl_->kernel_boxes.push_back(kernel_box(X_BaseBox, size_m));
}

void ArmCollisionWorld::add_cylinder(const std::string& name,
                                     const Eigen::Isometry3d& X_BaseCylinder, double radius_m,
                                     double length_m) {
  if (!(radius_m > 0.0 && length_m > 0.0 && std::isfinite(radius_m) && std::isfinite(length_m)))
    throw Error("collision world: cylinder '" + name + "' needs a positive radius and length");
  CollisionPrimitive p;
  p.kind = CollisionPrimitive::Kind::kCylinder;
  p.size_m = Eigen::Vector3d(radius_m, length_m, 0.0);
  p.X_LinkShape = X_BaseCylinder;
  impl_->boxes.push_back({name, make_shape(p)});
  // The kernels take the cylinder's bounding box, and the box inscribed in it as its solid part.
  KernelBox box = kernel_box(X_BaseCylinder, Eigen::Vector3d(2 * radius_m, 2 * radius_m, length_m));
  box.solid[0] = box.solid[1] = float(radius_m / std::sqrt(2.0));
  impl_->kernel_boxes.push_back(box);
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
  impl_->grid = DistanceGrid();
  if (points_m.empty()) return;
  if (impl_->spheres) {
    // The grid's distances reach past the largest sphere and the grid's margin (sqrt(3)
    // cells), so that a sphere clear of the points by a cell or more is called clear.
    impl_->grid = DistanceGrid(points_m, resolution_m,
                               impl_->spheres->max_radius_m() + 3.0 * resolution_m + 1e-4);
    impl_->points_radius = impl_->spheres->points_radii(impl_->points_unchecked);
  }
  impl_->points.geometry = std::make_shared<fcl::OcTreed>(std::shared_ptr<const octomap::OcTree>(
      impl_->options.octree_point_by_point ? points_octree_point_by_point(points_m, resolution_m)
                                           : points_octree(points_m, resolution_m)));
}

ContactReport ArmCollisionWorld::check(const Eigen::VectorXd& q) const {
  if (static_cast<std::size_t>(q.size()) != impl_->arm.dof() || !q.allFinite()) {
    throw Error("collision check: " + std::to_string(q.size()) + " joint values for the " +
                std::to_string(impl_->arm.dof()) + " joints of the arm (all finite)");
  }
  return impl_->spheres ? impl_->check_with_spheres(q) : impl_->check_exact(q);
}

ContactReport ArmCollisionWorld::Impl::check_exact(const Eigen::VectorXd& q) const {
  const std::vector<Eigen::Isometry3d>& poses = shape_poses_at(q);
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (links_collide(pairs[k].first, pairs[k].second, poses)) return self_report(k);
  const auto given = [&poses]() -> const std::vector<Eigen::Isometry3d>& { return poses; };
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].moving)
      if (auto contact = environment_contact(i, ~std::uint32_t(0), true, given)) return *contact;
  return {};
}

// The same contacts, in the same order, as check_exact(); FCL runs only where the spheres
// touch (and not at all in kSpheres mode).
ContactReport ArmCollisionWorld::Impl::check_with_spheres(const Eigen::VectorXd& q) const {
  thread_local SphereArm::Placement placement;
  thread_local std::vector<int> self_hits;
  thread_local std::vector<std::uint32_t> near;
  spheres->place(q.data(), placement);
  const bool exact = options.mode == CheckMode::kSpheresThenExact;
  const std::vector<Eigen::Isometry3d>* poses = nullptr;  // FCL's, made when first needed
  const auto fcl_poses = [&]() -> const std::vector<Eigen::Isometry3d>& {
    if (poses == nullptr) poses = &shape_poses_at(q);  // double, as check_exact()
    return *poses;
  };
  spheres->contacts(placement, kernel_boxes, grid, points_radius, self_hits, near);
  for (const int k : self_hits) {
    const auto [a, b] = pairs[std::size_t(k)];
    if (!exact || links_collide(a, b, fcl_poses())) return self_report(std::size_t(k));
  }
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].moving && near[i] != 0)
      if (auto contact = environment_contact(i, near[i], exact, fcl_poses)) return *contact;
  return {};
}

std::size_t ArmCollisionWorld::first_contact(const std::vector<Eigen::VectorXd>& qs) const {
  for (const Eigen::VectorXd& q : qs)
    if (static_cast<std::size_t>(q.size()) != impl_->arm.dof() || !q.allFinite()) (void)check(q);
  if (!impl_->spheres) {
    for (std::size_t i = 0; i < qs.size(); ++i)
      if (!impl_->check_exact(qs[i]).free()) return i;
    return qs.size();
  }
  const double* lanes[kBatchLanes];
  thread_local SphereArm::BatchContacts touched;
  const bool exact = impl_->options.mode == CheckMode::kSpheresThenExact;
  for (std::size_t first = 0; first < qs.size(); first += kBatchLanes) {
    const int count = int(std::min<std::size_t>(kBatchLanes, qs.size() - first));
    for (int l = 0; l < count; ++l) lanes[l] = qs[first + std::size_t(l)].data();
    const std::uint32_t flagged =
        impl_->spheres->contacts_batch(lanes, count, impl_->kernel_boxes, impl_->grid,
                                       impl_->points_radius, exact ? &touched : nullptr);
    // A flagged state is confirmed as check() confirms it: FCL only on the link pairs and the
    // links near the scene whose spheres touch (not every pair, as check_exact() would),
    // named by the batch itself; not at all where the batch shows the contact certain.
    for (int l = 0; l < count; ++l)
      if ((flagged >> l & 1U) && (!exact || (touched.certain >> l & 1U) ||
                                  impl_->confirm(qs[first + std::size_t(l)], touched, l)))
        return first + std::size_t(l);
  }
  return qs.size();
}

// check_with_spheres()'s FCL tests, on what a batch's spheres touched in `lane`.
bool ArmCollisionWorld::Impl::confirm(const Eigen::VectorXd& q,
                                      const SphereArm::BatchContacts& touched, int lane) const {
  const auto lit = [lane](std::uint32_t lanes) { return (lanes >> lane & 1U) != 0; };
  const std::vector<Eigen::Isometry3d>* poses = nullptr;
  const auto fcl_poses = [&]() -> const std::vector<Eigen::Isometry3d>& {
    if (poses == nullptr) poses = &shape_poses_at(q);
    return *poses;
  };
  for (const SphereArm::BatchContacts::Touch& pair : touched.self) {
    const auto [a, b] = pairs[std::size_t(pair.what)];
    if (lit(pair.lanes) && links_collide(a, b, fcl_poses())) return true;
  }
  // A link's boxes and points, as bits of SphereArm::contacts()'s `near`.
  const std::vector<SphereArm::BatchContacts::Touch>& scene = touched.scene;
  for (std::size_t n = 0; n < scene.size();) {
    const int link = scene[n].what;
    std::uint32_t near = 0;
    for (; n < scene.size() && scene[n].what == link; ++n)
      if (lit(scene[n].lanes))
        near |=
            std::uint32_t(1) << (scene[n].box < 0 ? SphereArm::kPointsBit
                                                  : std::min(scene[n].box, SphereArm::kLastBoxBit));
    if (near != 0 && environment_contact(std::size_t(link), near, true, fcl_poses)) return true;
  }
  return false;
}

ContactReport ArmCollisionWorld::check_tip_links(const Eigen::Isometry3d& X_BaseTip) const {
  if (!X_BaseTip.matrix().allFinite()) throw Error("collision check: the tip pose must be finite");
  std::vector<Eigen::Isometry3d> poses(impl_->shape_count);
  for (std::size_t i = 0; i < impl_->links.size(); ++i) {
    const Impl::Link& link = impl_->links[i];
    if (!link.rigid_with_tip) continue;
    for (std::size_t k = 0; k < link.shapes.size(); ++k)
      poses[link.first_shape + k] = X_BaseTip * link.X_TipLink * link.shapes[k].X_LinkShape;
    const auto given = [&poses]() -> const std::vector<Eigen::Isometry3d>& { return poses; };
    if (auto contact = impl_->environment_contact(i, ~std::uint32_t(0), true, given))
      return *contact;
  }
  return {};
}

std::vector<std::string> ArmCollisionWorld::tip_links() const {
  std::vector<std::string> names;
  for (const auto& link : impl_->links)
    if (link.rigid_with_tip) names.push_back(link.name);
  return names;
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

std::size_t ArmCollisionWorld::spheres() const {
  return impl_->spheres ? impl_->spheres->spheres() : 0;
}
double ArmCollisionWorld::overshoot_m() const {
  return impl_->spheres ? impl_->spheres->overshoot_m() : 0.0;
}
CheckMode ArmCollisionWorld::mode() const { return impl_->options.mode; }

}  // namespace antipode::collision
