#pragma once
// The fast collision path's inner loops over spheres (structure of arrays: x, y, z, radius),
// each built three times - for AVX-512, AVX2 and the baseline x86-64 instruction set - and
// run in the widest this CPU has. The loops are plain C++ that the compiler vectorizes (GCC
// reports each as vectorized with -fopt-info-vec); only the target attribute differs between
// the three builds. Written here rather than with a SIMD library because the loops are short
// and branch-free: the compiler's own vectorization reaches the width (bench/collision
// measures all three levels side by side).
//
// Units: metres, float. Threads: the functions keep no state; set_simd_level() must not run
// concurrently with them.

#include <cstdint>

namespace antipode::collision {

enum class SimdLevel { kBaseline, kAvx2, kAvx512 };

/// The level the kernels run at: the widest this CPU supports, unless lowered.
SimdLevel simd_level();
/// Lowers (or restores) the level, for measuring one against another; a level the CPU lacks
/// is clamped to the widest it has. Returns the level set.
SimdLevel set_simd_level(SimdLevel level);
const char* to_string(SimdLevel level);

/// A box: centre, rotation (rows of R_BoxWorld: world to box axes) and half sizes; and the
/// half sizes of a box about the same centre and axes that lies inside the obstacle the box
/// stands for (`solid`: the box itself, or the box inscribed in a cylinder).
struct KernelBox {
  float center[3];
  float rows[3][3];
  float half[3];
  float solid[3];
};

/// w = R l + t for n points (R: 9 floats, row by row).
void transform_points(const float* R, const float* t, const float* lx, const float* ly,
                      const float* lz, int n, float* wx, float* wy, float* wz);

/// bits[k] = the boxes sphere k (centre x, y, z, radius r) meets: bit b for boxes[b] (bit 30
/// for any from boxes[30] on). A sphere with a negative radius meets none.
void mark_in_boxes(const KernelBox* boxes, int box_count, const float* x, const float* y,
                   const float* z, const float* r, int n, std::uint32_t* bits);

/// For the spheres i < rows and j < columns (x, y, z, r hold `columns` spheres): hits[i] =
/// OR over j of allowed[j * rows + i] where spheres i and j overlap. Column j is tested
/// against the rows [row_begin[j], row_end[j]) only (multiples of 16): the allowed entries
/// of the others must be 0.
void mark_overlaps(const float* x, const float* y, const float* z, const float* r, int rows,
                   int columns, const std::int32_t* allowed, const std::int32_t* row_begin,
                   const std::int32_t* row_end, std::int32_t* hits);

/// The distance grid's test (distance_grid.hpp): touches[k] = 1 unless the value of the
/// cell holding centre k exceeds r[k] (beyond the grid: unless the distance to the
/// occupied box exceeds it).
struct KernelGrid {
  const float* clear_m;
  float inv_h;
  std::int32_t size[3];
  float origin_f[3];  ///< the first cell's index along each axis (multiples of h)
  float size_f[3];
  float box_min[3];
  float box_max[3];
};
void mark_near_points(const KernelGrid& grid, const float* x, const float* y, const float* z,
                      const float* r, int n, std::uint8_t* touches);

/// out[i] = min(out[i], add + in[i + offset]) for i in [0, n) (the distance grid's passes).
void min_shifted(float* out, const float* in, std::ptrdiff_t n, std::ptrdiff_t offset, float add);

/// Whether mark_batch() skips the tests that the links' bounding spheres show apart (the
/// default) or runs every one; the answer is the same. A process-wide switch for measuring
/// one against the other.
bool sphere_culling();
void set_sphere_culling(bool on);

/// Configurations checked at once by mark_batch(): one per lane of the widest vectors.
constexpr int kBatchLanes = 16;

/// An arm as mark_batch() reads it (sphere_arm.hpp builds it): the joint frames' constants
/// (screw_chain.hpp: X_BaseJoint_j = X_BaseJoint_{j-1} * C_j * Rz(q_j), or * Tz(q_j) where
/// prismatic[j]), the moving spheres (in their joint's frame; joint -1 for padding), the
/// fixed spheres (base frame), the sphere pairs to test (pair_a[p], a moving sphere, with
/// pair_b[p], a moving one or, from `moving` on, fixed sphere pair_b[p] - moving), and the
/// moving spheres box_sphere[p] to test against the robot's fixed boxes. Each sphere's inner
/// radius (inner, f_inner; 0: none) is that of a ball about its centre inside its link's
/// shape: where such a ball meets a box's solid part or another link's ball, the shapes
/// certainly meet.
///
/// The links' bounding spheres (link_bounds.hpp) let mark_batch() skip whole groups of tests:
/// bound b, in joint bound_joint[b]'s frame (-1: a fixed link, base frame), holds every
/// sphere of one link with room to spare for float rounding (its radius reaches past each
/// sphere's centre distance plus radius); the first `moving_bounds` are the moving links',
/// holding the moving spheres [bound_first[b], bound_end[b]), which together are every moving
/// sphere but the padding. The sphere pairs come grouped by link pair: group g covers pairs
/// [group_first[g], group_first[g + 1]), every one between bounds group_a[g] and group_b[g];
/// the box pairs likewise, group g the spheres box_sphere[p] of bound box_group_bound[g]
/// against robot box box_group_box[g]. A group whose bounds are apart in every lane is
/// skipped: the spheres inside them are apart too, so the answer is that of testing every
/// pair (`cull` false, for measuring one against the other).
struct KernelArm {
  int dof;
  const float* C;  ///< dof x 12: R row by row, then t
  const std::int32_t* prismatic;
  int moving;
  const std::int32_t* joint;
  const float *lx, *ly, *lz, *r;
  const float* points_r;  ///< radius against the points, -1 where unchecked
  const float* inner;
  const float *fx, *fy, *fz, *fr, *f_inner;
  const std::int32_t *pair_a, *pair_b;
  const std::int32_t* box_sphere;
  const KernelBox* robot_boxes;
  bool cull;
  int bounds, moving_bounds;
  const std::int32_t* bound_joint;
  const float *bound_lx, *bound_ly, *bound_lz, *bound_r;
  const std::int32_t *bound_first, *bound_end;
  int groups;
  const std::int32_t *group_a, *group_b, *group_first;
  int box_groups;
  const std::int32_t *box_group_bound, *box_group_box, *box_group_first;
};

/// Where mark_batch() found contacts, as bits by lane, so that a flagged lane can be confirmed
/// without placing its spheres again: per group of sphere pairs (`groups` entries), per group
/// of box pairs (`box_groups`), per moving bound and scene box (moving_bounds x box_count,
/// bound by bound), and per moving bound against the points (moving_bounds). A skipped
/// group's entry is 0. `certain`: the lanes in which some group that touches also shows a
/// contact of the shapes themselves (KernelArm's inner radii), so that no exact test is needed.
struct KernelContacts {
  std::uint32_t* groups;
  std::uint32_t* box_groups;
  std::uint32_t* scene_boxes;
  std::uint32_t* points;
  std::uint32_t* certain;
};

/// For kBatchLanes configurations (q: dof x kBatchLanes, joint by joint), the lanes whose
/// spheres touch anything - the robot (pairs), its fixed boxes, `boxes` or `grid` (null: no
/// points) - as bits. Unless `where` is null, also where: then every entry of `where` is
/// written (the test does not stop early when every lane already touches the robot).
/// `scratch` holds at least batch_scratch_floats(arm) floats.
std::uint32_t mark_batch(const KernelArm& arm, const KernelBox* boxes, int box_count,
                         const KernelGrid* grid, const float* q, float* scratch,
                         KernelContacts* where = nullptr);
std::size_t batch_scratch_floats(const KernelArm& arm);

}  // namespace antipode::collision
