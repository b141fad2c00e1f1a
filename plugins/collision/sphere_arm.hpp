#pragma once
// The fast collision path of an arm: every link's primitive shapes covered by spheres
// (sphere_cover.hpp), placed by the arm's joint values (screw_chain.hpp) and checked in SIMD
// loops (sphere_kernels.hpp) against the robot's other links, boxes and the observed points
// (distance_grid.hpp). The spheres hold the shapes, so each test is conservative: a link pair,
// box or point cloud it calls clear is clear of the real shapes; what it flags may still be
// clear (by at most the cover's overshoot, plus the grid's margin for points).
//
// Self-collision is tested in one pass of every moving sphere against every sphere of the
// links it may touch (the self pairs). One configuration at a time this pass is dense: for the
// few dozen spheres of an arm it is cheaper than the indirection a tree would add. Sixteen at
// a time (contacts_batch) it first tests one bounding sphere per link (link_bounds.hpp), and
// skips a link pair, or a link and box, that are apart in every configuration: for Baxter's
// 924 sphere pairs and 197 sphere-box pairs, among the cell's boxes, that takes a quarter of
// the time of testing them all (collision_bench, BM_CheckAmongBoxes_Spheres_Batch16 against
// its _Dense twin). The
// boxes of links that do not move (a robot's pedestal and torso) stay boxes, tested exactly
// against the moving spheres: large boxes need many spheres to be held closely.
//
// Frames and units: the robot's base frame, metres, radians. Threads: immutable after
// construction; the tests write only to the Placement or BatchContacts they are given (and
// contacts_batch to thread-local scratch), so concurrent checks with one of each per thread
// are safe.

#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"
#include "antipode/robot/robot_model.hpp"
#include "distance_grid.hpp"
#include "link_bounds.hpp"
#include "screw_chain.hpp"
#include "sphere_kernels.hpp"

namespace antipode::collision {

/// A box of `size_m` (full lengths) centred at X_BaseBox, as the kernels take it.
KernelBox kernel_box(const Eigen::Isometry3d& X_BaseBox, const Eigen::Vector3d& size_m);

class SphereArm {
 public:
  /// A link of the robot: its shapes (in its own frame) and where it hangs: from the arm
  /// chain's link `frame` (an index into KinematicChain::link_names()) by X_FrameLink, or,
  /// for frame -1, fixed at X_FrameLink in the base frame.
  struct Link {
    std::vector<CollisionPrimitive> shapes;
    int frame = -1;
    Eigen::Isometry3d X_FrameLink = Eigen::Isometry3d::Identity();
  };

  /// Where the spheres are for one configuration, and what they touch; reused between
  /// checks to avoid allocation.
  struct Placement {
    std::vector<float> x, y, z;                       // every sphere (the moving first)
    std::vector<std::int32_t> hits;                   // per moving sphere
    std::vector<std::uint8_t> marks;                  // per moving sphere
    std::vector<std::uint32_t> robot_bits, box_bits;  // per moving sphere
    std::vector<Pose3f> X_BaseJoint;                  // the arm's joint frames
    std::vector<int> pairs;                           // scratch
    std::uint64_t arm = 0;  // the SphereArm whose fixed spheres x, y, z hold
  };

  /// Covers every link with spheres (at most `max_overshoot_m` beyond its shapes where the
  /// cover can, sphere_cover.hpp). `self_pairs` are the link pairs (indices into `links`)
  /// to test against each other. Throws antipode::Error for a frame index off the arm.
  SphereArm(const KinematicChain& arm, const std::vector<Link>& links,
            const std::vector<std::pair<std::size_t, std::size_t>>& self_pairs,
            double max_overshoot_m);
  // The kernels' view points into the object's own lists: neither copied nor moved.
  SphereArm(const SphereArm&) = delete;
  SphereArm& operator=(const SphereArm&) = delete;

  /// Places the spheres for `q_rad` (the arm's dof() values).
  void place(const double* q_rad, Placement& p) const;

  /// What the placed spheres touch: the indices into `self_pairs` whose links' spheres (or
  /// a fixed link's boxes) meet, in order, into `self`; and per link (indices into `links`;
  /// 0 for a fixed link), into `near`, the obstacles its spheres may touch as bits: bit b for
  /// boxes[b] (bit kLastBoxBit for any box from it on) and kPointsBit for the grid's occupied
  /// cubes. `points_radius` is points_radii()'s.
  static constexpr int kLastBoxBit = 30;
  static constexpr int kPointsBit = 31;
  void contacts(Placement& p, const std::vector<KernelBox>& boxes, const DistanceGrid& grid,
                const std::vector<float>& points_radius, std::vector<int>& self,
                std::vector<std::uint32_t>& near) const;
  /// Where a batch's spheres touch, so that a flagged lane can be confirmed without placing
  /// its spheres again: each self pair that touches in some lane (`what`, an index into
  /// `self_pairs`), and each link (`what`, an index into `links`) that touches a scene box
  /// (`box`, an index into the boxes) or the points (`box` -1), with the lanes where it
  /// does as bits; a link's entries come together. `certain`: the lanes in which the shapes
  /// themselves certainly meet something (a sphere's inner ball, which lies inside its shape,
  /// meets a box's solid part or another link's inner ball), so that no exact test need
  /// confirm them. Reused between batches to avoid allocation.
  struct BatchContacts {
    struct Touch {
      int what = 0;
      int box = -1;
      std::uint32_t lanes = 0;
    };
    std::vector<Touch> self, scene;
    std::uint32_t certain = 0;
    std::vector<std::uint32_t> pair_lanes, kernel;  // scratch
  };
  /// Which of up to kBatchLanes configurations (q_rad[lane], each dof() values) may touch
  /// anything (the same tests as contacts(), all at once), as bits by lane; and where, into
  /// `where` unless it is null (filled only when some lane touches).
  std::uint32_t contacts_batch(const double* const* q_rad, int count,
                               const std::vector<KernelBox>& boxes, const DistanceGrid& grid,
                               const std::vector<float>& points_radius,
                               BatchContacts* where = nullptr) const;

  /// The spheres' radii for the points test: -1 (never touching) for the spheres of the
  /// links marked in `unchecked` (one entry per link), of the fixed links and the padding.
  std::vector<float> points_radii(const std::vector<char>& unchecked) const;

  /// The spheres of the links (without padding).
  std::size_t spheres() const { return spheres_; }
  /// The largest overshoot of any moving link's cover.
  double overshoot_m() const { return overshoot_m_; }
  /// The largest radius of a sphere that moves with the arm (the farthest the points test
  /// ever looks).
  double max_radius_m() const;

 private:
  void add_link(int i, const Link& link, double max_overshoot_m);
  void add_sphere(const Eigen::Vector3d& centre_m, double radius_m, double inner_m, int owner);
  void pad(std::size_t multiple);
  void allow_pairs(const std::vector<std::pair<std::size_t, std::size_t>>& self_pairs);
  void group_pairs();
  void make_kernel_arm();
  void name_contacts(const KernelContacts& found, std::size_t box_count, std::uint32_t lanes,
                     BatchContacts& where) const;
  void self_contacts(Placement& p, std::vector<int>& out) const;

  // The links' spheres in one list: a moving link's centres in its joint frame (screw_chain.hpp),
  // a fixed link's in the base frame. The moving links come first, by joint, then spheres of
  // radius -1 far away (owner -1, touching nothing) up to a multiple of the widest kernels'
  // lanes, so that no loop over the moving spheres ends in a scalar remainder; then the fixed
  // links, padded the same way.
  std::vector<float> lx_, ly_, lz_, r_;
  std::vector<float> inner_;  // the inner ball's radius, less a margin (0: none)
  std::vector<int> owner_;    // the link of each sphere, -1 for padding
  std::vector<std::pair<int, int>> joint_spheres_;  // [first, end) of the moving, per joint
  std::vector<int> link_joint_;                     // per link, -1 when fixed
  int moving_ = 0;                                  // the moving spheres and their padding
  std::size_t spheres_ = 0;                         // without padding
  // Self-collision: allowed_[j * moving_ + i] is -1 when sphere j (j > i) may touch moving
  // sphere i (their links are a self pair), else 0; allowed_boxes_[i] the fixed boxes (bits
  // of robot_bits) sphere i may touch; pair_of_ the self pair of two links, or -1.
  std::vector<std::int32_t> allowed_;
  std::vector<std::vector<int>> allowed_rows_;     // per moving sphere i, the spheres j
  std::vector<std::int32_t> row_begin_, row_end_;  // per sphere j, the rows it is tested on
  std::vector<std::uint32_t> allowed_boxes_;
  std::vector<int> pair_of_;
  std::size_t self_pairs_ = 0;
  std::size_t links_ = 0;
  std::vector<KernelBox> fixed_boxes_;
  std::vector<int> fixed_box_owner_;
  // What contacts_batch() gives the kernels: the joints' constants, each moving sphere's
  // joint, and the allowed sphere pairs and sphere-box pairs as flat lists.
  std::vector<float> joint_constants_;
  std::vector<std::int32_t> joint_prismatic_, sphere_joint_;
  std::vector<std::int32_t> batch_a_, batch_b_, box_sphere_, box_index_;
  // Each link's spheres held by one bounding sphere, and the pairs above grouped by the
  // bounds they lie between (link_bounds.hpp).
  LinkBounds bounds_;
  PairGroups self_groups_, box_groups_;
  KernelArm kernel_{};
  ScrewChain chain_;
  double overshoot_m_ = 0.0;
  std::uint64_t id_ = 0;
};

}  // namespace antipode::collision
