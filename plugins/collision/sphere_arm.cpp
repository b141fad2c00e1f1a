#include "sphere_arm.hpp"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <numeric>
#include <string>

#include "antipode/core/error.hpp"
#include "link_bounds.hpp"
#include "sphere_cover.hpp"

namespace antipode::collision {

namespace {

// Float rounding of the placed centres (float forward kinematics over a metre or two): radii
// grow by this to stay safe.
constexpr double kRounding_m = 1e-4;
// The widest kernels' lanes (AVX-512, 16 floats): loops over spheres run in whole multiples.
constexpr std::size_t kLanes = 16;
const Eigen::Vector3d kFarAway_m = Eigen::Vector3d::Constant(1e6);
// A link's bounding sphere reaches this much beyond its spheres: float rounding places the
// bound and the spheres from the same joint frame, off by far less.
constexpr double kBoundMargin_m = 1e-4;
// A sphere's inner ball (sphere_cover.hpp) shrinks by this before it may show a certain
// contact: the float rounding of the placed centres, and FCL's own tolerance, are far smaller.
constexpr double kCertainMargin_m = 1e-3;

}  // namespace

KernelBox kernel_box(const Eigen::Isometry3d& X_BaseBox, const Eigen::Vector3d& size_m) {
  KernelBox box{};
  for (int i = 0; i < 3; ++i) {
    box.center[i] = float(X_BaseBox.translation()(i));
    box.half[i] = float(0.5 * size_m(i));
    box.solid[i] = box.half[i];
    for (int j = 0; j < 3; ++j) box.rows[i][j] = float(X_BaseBox.linear()(j, i));
  }
  return box;
}

SphereArm::SphereArm(const KinematicChain& arm, const std::vector<Link>& links,
                     const std::vector<std::pair<std::size_t, std::size_t>>& self_pairs,
                     double max_overshoot_m)
    : links_(links.size()), chain_(arm) {
  static std::atomic<std::uint64_t> next_id{1};
  id_ = next_id++;
  for (const Link& link : links)
    if (link.frame >= int(arm.link_names().size()))
      throw Error("sphere arm: link frame " + std::to_string(link.frame) + " is off the arm");
  // A link hangs from the joint frame before its chain link (-1: it does not move).
  link_joint_.assign(links.size(), -1);
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].frame >= 0) link_joint_[i] = chain_.joint_of(std::size_t(links[i].frame));
  // Moving links first, by joint; then the fixed ones.
  std::vector<int> order(links.size());
  std::iota(order.begin(), order.end(), 0);
  const int last = int(chain_.dof());
  const auto joint = [&](int i) {
    return link_joint_[std::size_t(i)] < 0 ? last : link_joint_[std::size_t(i)];
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return joint(a) < joint(b); });
  joint_spheres_.assign(chain_.dof(), {0, 0});
  bool padded = false;
  for (const int i : order) {
    if (link_joint_[std::size_t(i)] < 0 && !padded) {
      pad(kLanes);
      moving_ = int(owner_.size());
      padded = true;
    }
    add_link(i, links[std::size_t(i)], max_overshoot_m);
  }
  if (!padded) {
    pad(kLanes);
    moving_ = int(owner_.size());
  }
  pad(kLanes);
  allow_pairs(self_pairs);
  group_pairs();
  for (std::size_t j = 0; j < chain_.dof(); ++j) {
    const Pose3f& C = chain_.constant(j);
    joint_constants_.insert(joint_constants_.end(), C.R, C.R + 9);
    joint_constants_.insert(joint_constants_.end(), C.t, C.t + 3);
    joint_prismatic_.push_back(chain_.prismatic(j) ? 1 : 0);
  }
  for (int k = 0; k < moving_; ++k)
    sphere_joint_.push_back(
        owner_[std::size_t(k)] < 0 ? -1 : link_joint_[std::size_t(owner_[std::size_t(k)])]);
  make_kernel_arm();
}

void SphereArm::add_sphere(const Eigen::Vector3d& centre_m, double radius_m, double inner_m,
                           int owner) {
  lx_.push_back(float(centre_m.x()));
  ly_.push_back(float(centre_m.y()));
  lz_.push_back(float(centre_m.z()));
  r_.push_back(float(radius_m));
  inner_.push_back(float(std::max(0.0, inner_m - kCertainMargin_m)));
  owner_.push_back(owner);
}

void SphereArm::pad(std::size_t multiple) {
  while (owner_.size() % multiple != 0) add_sphere(kFarAway_m, -1.0, 0.0, -1);
}

void SphereArm::add_link(int i, const Link& link, double max_overshoot_m) {
  const int joint = link_joint_[std::size_t(i)];
  // Where the link's shapes are: in its joint's frame, or in the base frame.
  const Eigen::Isometry3d X_Link =
      link.frame < 0 ? link.X_FrameLink
                     : chain_.X_JointLink(std::size_t(link.frame)) * link.X_FrameLink;
  const int first = int(owner_.size());
  for (const CollisionPrimitive& shape : link.shapes) {
    if (joint < 0 && shape.kind == CollisionPrimitive::Kind::kBox) {  // stays a box
      fixed_boxes_.push_back(kernel_box(X_Link * shape.X_LinkShape, shape.size_m));
      fixed_box_owner_.push_back(i);
      continue;
    }
    const SphereCover cover = cover_with_spheres(shape, max_overshoot_m);
    if (joint >= 0) overshoot_m_ = std::max(overshoot_m_, cover.overshoot_m);
    for (const Sphere& s : cover.spheres)
      add_sphere(X_Link * s.center_m, s.radius_m + kRounding_m, s.inner_m, i);
    spheres_ += cover.spheres.size();
  }
  if (joint >= 0) {
    auto& range = joint_spheres_[std::size_t(joint)];
    if (range.first == range.second) range.first = first;
    range.second = int(owner_.size());
  }
}

void SphereArm::allow_pairs(const std::vector<std::pair<std::size_t, std::size_t>>& self_pairs) {
  self_pairs_ = self_pairs.size();
  pair_of_.assign(links_ * links_, -1);
  for (std::size_t k = 0; k < self_pairs.size(); ++k) {
    const auto [a, b] = self_pairs[k];
    pair_of_[a * links_ + b] = pair_of_[b * links_ + a] = int(k);
  }
  const std::size_t all = owner_.size(), rows = std::size_t(moving_);
  allowed_.assign(all * rows, 0);
  allowed_boxes_.assign(rows, 0);
  allowed_rows_.assign(all, {});
  row_begin_.assign(all, 0);
  row_end_.assign(all, 0);
  for (std::size_t j = 0; j < all; ++j) {
    if (owner_[j] < 0) continue;
    for (std::size_t i = 0; i < std::min(j, rows); ++i) {
      if (owner_[i] < 0 || pair_of_[std::size_t(owner_[i]) * links_ + std::size_t(owner_[j])] < 0)
        continue;
      allowed_[j * rows + i] = -1;
      allowed_rows_[i].push_back(int(j));
      batch_a_.push_back(std::int32_t(i));
      batch_b_.push_back(std::int32_t(j));
      if (row_end_[j] == 0) row_begin_[j] = std::int32_t(i / kLanes * kLanes);
      row_end_[j] = std::int32_t((i / kLanes + 1) * kLanes);
    }
  }
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t k = 0; owner_[i] >= 0 && k < fixed_boxes_.size(); ++k)
      if (pair_of_[std::size_t(owner_[i]) * links_ + std::size_t(fixed_box_owner_[k])] >= 0) {
        allowed_boxes_[i] |= std::uint32_t(1) << std::min(int(k), kLastBoxBit);
        box_sphere_.push_back(std::int32_t(i));
        box_index_.push_back(std::int32_t(k));
      }
}

// The sphere pairs grouped by the bounds of their links, the box pairs by the bound of the
// sphere's link and the box.
void SphereArm::group_pairs() {
  bounds_ = bound_links(owner_, link_joint_, lx_, ly_, lz_, r_, kBoundMargin_m);
  const auto bound = [this](std::int32_t sphere) {
    return bounds_.of_link[std::size_t(owner_[std::size_t(sphere)])];
  };
  self_groups_ = group_by_key(batch_a_, batch_b_, [&](std::size_t p) {
    return std::pair{bound(batch_a_[p]), bound(batch_b_[p])};
  });
  box_groups_ = group_by_key(box_sphere_, box_index_, [&](std::size_t p) {
    return std::pair{bound(box_sphere_[p]), int(box_index_[p])};
  });
}

double SphereArm::max_radius_m() const {
  return moving_ == 0 ? 0.0 : double(*std::max_element(r_.begin(), r_.begin() + moving_));
}

void SphereArm::place(const double* q_rad, Placement& p) const {
  p.X_BaseJoint.resize(chain_.dof());
  chain_.joint_poses(q_rad, p.X_BaseJoint.data());
  if (p.arm != id_) {  // the fixed spheres, once per arm
    p.x = lx_;
    p.y = ly_;
    p.z = lz_;
    p.arm = id_;
  }
  for (std::size_t j = 0; j < joint_spheres_.size(); ++j) {
    const auto [first, end] = joint_spheres_[j];
    if (first == end) continue;
    const Pose3f& X = p.X_BaseJoint[j];
    transform_points(X.R, X.t, lx_.data() + first, ly_.data() + first, lz_.data() + first,
                     end - first, p.x.data() + first, p.y.data() + first, p.z.data() + first);
  }
}

void SphereArm::contacts(Placement& p, const std::vector<KernelBox>& boxes,
                         const DistanceGrid& grid, const std::vector<float>& points_radius,
                         std::vector<int>& self, std::vector<std::uint32_t>& near) const {
  // Per moving sphere, the robot's fixed boxes and the scene's boxes it meets.
  p.robot_bits.resize(std::size_t(moving_));
  p.box_bits.resize(std::size_t(moving_));
  mark_in_boxes(fixed_boxes_.data(), int(fixed_boxes_.size()), p.x.data(), p.y.data(), p.z.data(),
                r_.data(), moving_, p.robot_bits.data());
  mark_in_boxes(boxes.data(), int(boxes.size()), p.x.data(), p.y.data(), p.z.data(), r_.data(),
                moving_, p.box_bits.data());
  self_contacts(p, self);
  near.assign(links_, 0);
  const auto owner = [this](int k) { return owner_[std::size_t(k)]; };
  for (int k = 0; k < moving_; ++k)
    if (owner(k) >= 0) near[std::size_t(owner(k))] |= p.box_bits[std::size_t(k)];
  if (grid.empty() || points_radius.size() != std::size_t(moving_)) return;
  p.marks.resize(std::size_t(moving_));
  grid.mark_touching(p.x.data(), p.y.data(), p.z.data(), points_radius.data(), moving_,
                     p.marks.data());
  for (int k = 0; k < moving_; ++k)
    if (p.marks[std::size_t(k)] && owner(k) >= 0)
      near[std::size_t(owner(k))] |= std::uint32_t(1) << kPointsBit;
}

// One dense pass finds the moving spheres that touch anything of a self pair; the pairs
// themselves are then named from those spheres alone.
void SphereArm::self_contacts(Placement& p, std::vector<int>& out) const {
  out.clear();
  p.hits.resize(std::size_t(moving_));
  mark_overlaps(p.x.data(), p.y.data(), p.z.data(), r_.data(), moving_, int(owner_.size()),
                allowed_.data(), row_begin_.data(), row_end_.data(), p.hits.data());
  p.pairs.clear();
  for (std::size_t i = 0; i < std::size_t(moving_); ++i) {
    const bool box = (p.robot_bits[i] & allowed_boxes_[i]) != 0;
    if (!p.hits[i] && !box) continue;
    const std::size_t a = std::size_t(owner_[i]);
    for (std::size_t n = 0; p.hits[i] && n < allowed_rows_[i].size(); ++n) {
      const std::size_t j = std::size_t(allowed_rows_[i][n]);
      const float dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
      const float reach = r_[i] + r_[j];
      if (dx * dx + dy * dy + dz * dz <= reach * reach)
        p.pairs.push_back(pair_of_[a * links_ + std::size_t(owner_[j])]);
    }
    for (std::size_t k = 0; box && k < fixed_boxes_.size(); ++k) {
      // Boxes from kLastBoxBit on share a bit: name only those of links paired with this one.
      const int pair = pair_of_[a * links_ + std::size_t(fixed_box_owner_[k])];
      if (pair >= 0 && (p.robot_bits[i] & allowed_boxes_[i] &
                        (std::uint32_t(1) << std::min(int(k), kLastBoxBit))))
        p.pairs.push_back(pair);
    }
  }
  std::sort(p.pairs.begin(), p.pairs.end());
  std::unique_copy(p.pairs.begin(), p.pairs.end(), std::back_inserter(out));
}

// The kernels' view of the arm (KernelArm): pointers into this object's own lists, which do
// not change after construction; the points' radii and the culling switch are set per call.
void SphereArm::make_kernel_arm() {
  KernelArm& a = kernel_;
  a.dof = int(chain_.dof());
  a.C = joint_constants_.data();
  a.prismatic = joint_prismatic_.data();
  a.moving = moving_;
  a.joint = sphere_joint_.data();
  a.lx = lx_.data();
  a.ly = ly_.data();
  a.lz = lz_.data();
  a.r = r_.data();
  a.inner = inner_.data();
  a.fx = lx_.data() + moving_;
  a.fy = ly_.data() + moving_;
  a.fz = lz_.data() + moving_;
  a.fr = r_.data() + moving_;
  a.f_inner = inner_.data() + moving_;
  a.pair_a = batch_a_.data();
  a.pair_b = batch_b_.data();
  a.box_sphere = box_sphere_.data();
  a.robot_boxes = fixed_boxes_.data();
  a.bounds = int(bounds_.link.size());
  a.moving_bounds = bounds_.moving;
  a.bound_joint = bounds_.joint.data();
  a.bound_lx = bounds_.x.data();
  a.bound_ly = bounds_.y.data();
  a.bound_lz = bounds_.z.data();
  a.bound_r = bounds_.radius.data();
  a.bound_first = bounds_.first.data();
  a.bound_end = bounds_.end.data();
  a.groups = int(self_groups_.a.size());
  a.group_a = self_groups_.a.data();
  a.group_b = self_groups_.b.data();
  a.group_first = self_groups_.first.data();
  a.box_groups = int(box_groups_.a.size());
  a.box_group_bound = box_groups_.a.data();
  a.box_group_box = box_groups_.b.data();
  a.box_group_first = box_groups_.first.data();
}

std::uint32_t SphereArm::contacts_batch(const double* const* q_rad, int count,
                                        const std::vector<KernelBox>& boxes,
                                        const DistanceGrid& grid,
                                        const std::vector<float>& points_radius,
                                        BatchContacts* where) const {
  if (count < 1 || count > kBatchLanes)
    throw InternalError("sphere arm: a batch of " + std::to_string(count) + " configurations");
  KernelArm a = kernel_;
  a.points_r = points_radius.data();
  a.cull = sphere_culling();
  // Joint values lane by lane, the last configuration repeated in unused lanes.
  thread_local std::vector<float> q;
  thread_local std::vector<float> scratch;
  q.resize(chain_.dof() * kBatchLanes);
  for (std::size_t j = 0; j < chain_.dof(); ++j)
    for (int l = 0; l < kBatchLanes; ++l)
      q[j * kBatchLanes + std::size_t(l)] =
          float(chain_.reduced(j, q_rad[std::min(l, count - 1)][j]));
  scratch.resize(batch_scratch_floats(a));
  KernelGrid g{};
  const bool points = !grid.empty() && points_radius.size() == std::size_t(moving_);
  if (points) g = grid.kernel();
  KernelContacts found{};
  if (where != nullptr) {
    const std::size_t scene = std::size_t(bounds_.moving) * boxes.size();
    where->kernel.resize(self_groups_.a.size() + box_groups_.a.size() + scene +
                         std::size_t(bounds_.moving));
    found.groups = where->kernel.data();
    found.box_groups = found.groups + self_groups_.a.size();
    found.scene_boxes = found.box_groups + box_groups_.a.size();
    found.points = found.scene_boxes + scene;
    found.certain = &where->certain;
  }
  std::uint32_t lanes = mark_batch(a, boxes.data(), int(boxes.size()), points ? &g : nullptr,
                                   q.data(), scratch.data(), where != nullptr ? &found : nullptr);
  if (count < kBatchLanes) lanes &= (std::uint32_t(1) << count) - 1;
  if (where != nullptr) where->certain &= lanes;
  if (where != nullptr && lanes != 0) name_contacts(found, boxes.size(), lanes, *where);
  return lanes;
}

// The kernel's groups by the self pairs and links they test.
void SphereArm::name_contacts(const KernelContacts& found, std::size_t box_count,
                              std::uint32_t lanes, BatchContacts& where) const {
  const auto link = [this](int bound) { return std::size_t(bounds_.link[std::size_t(bound)]); };
  std::vector<std::uint32_t>& pair_lanes = where.pair_lanes;
  pair_lanes.assign(self_pairs_, 0);
  for (std::size_t g = 0; g < self_groups_.a.size(); ++g)
    if (found.groups[g] & lanes)
      pair_lanes[std::size_t(
          pair_of_[link(self_groups_.a[g]) * links_ + link(self_groups_.b[g])])] |= found.groups[g];
  for (std::size_t g = 0; g < box_groups_.a.size(); ++g)
    if (found.box_groups[g] & lanes) {
      const std::size_t owner = std::size_t(fixed_box_owner_[std::size_t(box_groups_.b[g])]);
      pair_lanes[std::size_t(pair_of_[link(box_groups_.a[g]) * links_ + owner])] |=
          found.box_groups[g];
    }
  where.self.clear();
  for (std::size_t k = 0; k < self_pairs_; ++k)
    if (pair_lanes[k] & lanes) where.self.push_back({int(k), -1, pair_lanes[k]});
  where.scene.clear();
  for (int b = 0; b < bounds_.moving; ++b) {
    const int owner = int(link(b));
    for (std::size_t c = 0; c < box_count; ++c)
      if (const std::uint32_t touch = found.scene_boxes[std::size_t(b) * box_count + c] & lanes)
        where.scene.push_back({owner, int(c), touch});
    if (const std::uint32_t touch = found.points[b] & lanes)
      where.scene.push_back({owner, -1, touch});
  }
}

std::vector<float> SphereArm::points_radii(const std::vector<char>& unchecked) const {
  std::vector<float> radii(static_cast<std::size_t>(moving_));
  for (int k = 0; k < moving_; ++k) {
    const int owner = owner_[std::size_t(k)];
    const bool skip =
        owner < 0 || (std::size_t(owner) < unchecked.size() && unchecked[std::size_t(owner)]);
    radii[std::size_t(k)] = skip ? -1.0f : r_[std::size_t(k)];
  }
  return radii;
}

}  // namespace antipode::collision
