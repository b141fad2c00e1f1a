#include "sphere_kernels.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace antipode::collision {

namespace {

// Each loop is written once, inlined into three functions that differ only in their target.
#define ANTIPODE_INLINE inline __attribute__((always_inline))
#define ANTIPODE_AVX2 __attribute__((target("avx2,fma")))
#define ANTIPODE_AVX512 __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,avx2,fma")))

// max(t, 0) as arithmetic: GCC does not vectorize std::max on floats for AVX2 (NaN rules).
ANTIPODE_INLINE float positive_part(float t) { return 0.5f * (t + std::abs(t)); }
// min(max(t, 0), hi) for hi >= 0, the same way.
ANTIPODE_INLINE float clamp_to(float t, float hi) {
  return hi - positive_part(hi - positive_part(t));
}

ANTIPODE_INLINE void transform_loop(const float* __restrict R, const float* __restrict t,
                                    const float* __restrict lx, const float* __restrict ly,
                                    const float* __restrict lz, int n, float* __restrict wx,
                                    float* __restrict wy, float* __restrict wz) {
  for (int k = 0; k < n; ++k) {
    wx[k] = R[0] * lx[k] + R[1] * ly[k] + R[2] * lz[k] + t[0];
    wy[k] = R[3] * lx[k] + R[4] * ly[k] + R[5] * lz[k] + t[1];
    wz[k] = R[6] * lx[k] + R[7] * ly[k] + R[8] * lz[k] + t[2];
  }
}

// The squared distance from (x, y, z) to the box: the point in the box's axes, and how far it
// lies outside the box along each.
ANTIPODE_INLINE float gap2(const KernelBox& b, float x, float y, float z) {
  const float dx = x - b.center[0], dy = y - b.center[1], dz = z - b.center[2];
  const float u = b.rows[0][0] * dx + b.rows[0][1] * dy + b.rows[0][2] * dz;
  const float v = b.rows[1][0] * dx + b.rows[1][1] * dy + b.rows[1][2] * dz;
  const float w = b.rows[2][0] * dx + b.rows[2][1] * dy + b.rows[2][2] * dz;
  const float ou = positive_part(std::abs(u) - b.half[0]);
  const float ov = positive_part(std::abs(v) - b.half[1]);
  const float ow = positive_part(std::abs(w) - b.half[2]);
  return ou * ou + ov * ov + ow * ow;
}

ANTIPODE_INLINE void boxes_loop(const KernelBox* boxes, int box_count, const float* __restrict x,
                                const float* __restrict y, const float* __restrict z,
                                const float* __restrict r, int n, std::uint32_t* __restrict bits) {
  for (int k = 0; k < n; ++k) bits[k] = 0;
  for (int i = 0; i < box_count; ++i) {
    const KernelBox b = boxes[i];  // a copy: its fields stay in registers
    const std::uint32_t bit = std::uint32_t(1) << std::min(i, 30);
    for (int k = 0; k < n; ++k) {
      const std::uint32_t touch =
          std::uint32_t(gap2(b, x[k], y[k], z[k]) <= r[k] * r[k]) & std::uint32_t(r[k] >= 0.0f);
      bits[k] |= touch * bit;
    }
  }
}

ANTIPODE_INLINE void overlaps_loop(const float* __restrict x, const float* __restrict y,
                                   const float* __restrict z, const float* __restrict r, int rows,
                                   int columns, const std::int32_t* __restrict allowed,
                                   const std::int32_t* __restrict row_begin,
                                   const std::int32_t* __restrict row_end, std::int32_t* hits) {
  for (int i = 0; i < rows; ++i) hits[i] = 0;
  for (int j = 0; j < columns; ++j) {
    const float xj = x[j], yj = y[j], zj = z[j], rj = r[j];
    const std::int32_t* allowed_j = allowed + std::ptrdiff_t(j) * rows;
    for (int i = row_begin[j]; i < row_end[j]; ++i) {
      const float dx = x[i] - xj, dy = y[i] - yj, dz = z[i] - zj, reach = r[i] + rj;
      const std::int32_t overlap = dx * dx + dy * dy + dz * dz <= reach * reach ? -1 : 0;
      hits[i] |= allowed_j[i] & overlap;
    }
  }
}

// Branch-free (bitwise & and | on integers, cell 0 standing in outside the grid, no floor),
// reading the grid's fields into locals first: written so, GCC vectorizes it.
ANTIPODE_INLINE void grid_loop(const KernelGrid& g, const float* __restrict x,
                               const float* __restrict y, const float* __restrict z,
                               const float* __restrict r, int n, std::uint8_t* __restrict touches) {
  const float* __restrict clear_m = g.clear_m;
  const float inv_h = g.inv_h;
  const float lo_x = g.box_min[0], lo_y = g.box_min[1], lo_z = g.box_min[2];
  const float hi_x = g.box_max[0], hi_y = g.box_max[1], hi_z = g.box_max[2];
  const float o_x = g.origin_f[0], o_y = g.origin_f[1], o_z = g.origin_f[2];
  const float s_x = g.size_f[0], s_y = g.size_f[1], s_z = g.size_f[2];
  const std::int32_t n_x = g.size[0], n_y = g.size[1], n_z = g.size[2];
  for (int k = 0; k < n; ++k) {
    // Outside the occupied cubes' bounding box by this much along each axis.
    const float ox = positive_part(lo_x - x[k]) + positive_part(x[k] - hi_x);
    const float oy = positive_part(lo_y - y[k]) + positive_part(y[k] - hi_y);
    const float oz = positive_part(lo_z - z[k]) + positive_part(z[k] - hi_z);
    const float outside2 = ox * ox + oy * oy + oz * oz;
    // The cell plus one, clamped to [0, size + 1] so that the conversion truncates a
    // non-negative value (a floor) and stays in range; then the cell.
    const float fi = clamp_to(x[k] * inv_h - o_x + 1.0f, s_x + 1.0f);
    const float fj = clamp_to(y[k] * inv_h - o_y + 1.0f, s_y + 1.0f);
    const float fl = clamp_to(z[k] * inv_h - o_z + 1.0f, s_z + 1.0f);
    const std::int32_t i = std::int32_t(fi) - 1, j = std::int32_t(fj) - 1;
    const std::int32_t l = std::int32_t(fl) - 1;
    const std::int32_t inside = (i >= 0) & (i < n_x) & (j >= 0) & (j < n_y) & (l >= 0) & (l < n_z);
    // A 32-bit index (a grid has at most 16e6 cells): with a 64-bit one GCC left the loop
    // scalar where the batch inlines it.
    const std::int32_t cell = ((l * n_y + j) * n_x + i) * inside;
    const float clear = clear_m[cell];
    const std::int32_t near =
        (inside & (clear <= r[k])) | ((1 - inside) & (outside2 <= r[k] * r[k]));
    touches[k] = std::uint8_t(near & (r[k] >= 0.0f));
  }
}

// sin and cos of x (|x| < 100) in float, branch-free so that a loop over lanes vectorizes:
// the quadrant n = round(2 x / pi), the remainder r = x - n pi / 2 (Cody and Waite's three
// parts of pi / 2), Cephes' minimax polynomials of sinf and cosf on [-pi/4, pi/4] (errors
// near 1e-7), and the quadrant's swap and signs.
ANTIPODE_INLINE void sin_cos(float x, float& sin_x, float& cos_x) {
  const std::int32_t n = std::int32_t(x * 0.636619772f + std::copysign(0.5f, x));
  const float fn = float(n);
  const float r =
      ((x - fn * 1.5703125f) - fn * 4.837512969970703125e-4f) - fn * 7.54978995489188216e-8f;
  const float r2 = r * r;
  const float s =
      r + r * r2 * (-1.6666654611e-1f + r2 * (8.3321608736e-3f + r2 * -1.9515295891e-4f));
  const float c =
      1.0f - 0.5f * r2 +
      r2 * r2 *
          (4.166664568298827e-2f + r2 * (-1.388731625493765e-3f + r2 * 2.443315711809948e-5f));
  const float swap = float(n & 1);  // odd quadrants exchange sin and cos
  const float sin_sign = 1.0f - 2.0f * float((n >> 1) & 1);
  const float cos_sign = 1.0f - 2.0f * float(((n + 1) >> 1) & 1);
  sin_x = sin_sign * (s + swap * (c - s));
  cos_x = cos_sign * (c + swap * (s - c));
}

constexpr std::ptrdiff_t L = kBatchLanes;

// The joint frames of every lane: scratch[j * 12 * L + e * L + lane], e the entry of [R | t].
ANTIPODE_INLINE void batch_kinematics(const KernelArm& a, const float* __restrict q,
                                      float* __restrict frames) {
  float M[12][L], T[12][L];
  for (int e = 0; e < 12; ++e)
    for (int l = 0; l < L; ++l) M[e][l] = (e == 0 || e == 4 || e == 8) ? 1.0f : 0.0f;
  for (int j = 0; j < a.dof; ++j) {
    const float* C = a.C + 12 * std::ptrdiff_t(j);
    for (std::ptrdiff_t row = 0; row < 3; ++row)
      for (int l = 0; l < L; ++l) {
        const float m0 = M[3 * row][l], m1 = M[3 * row + 1][l], m2 = M[3 * row + 2][l];
        for (int col = 0; col < 3; ++col)
          T[3 * row + col][l] = m0 * C[col] + m1 * C[3 + col] + m2 * C[6 + col];
        T[9 + row][l] = m0 * C[9] + m1 * C[10] + m2 * C[11] + M[9 + row][l];
      }
    const float* qj = q + j * L;
    if (a.prismatic[j]) {
      for (std::ptrdiff_t row = 0; row < 3; ++row)
        for (int l = 0; l < L; ++l) T[9 + row][l] += qj[l] * T[3 * row + 2][l];
    } else {
      float c[L], s[L];
      for (int l = 0; l < L; ++l) sin_cos(qj[l], s[l], c[l]);
      for (std::ptrdiff_t row = 0; row < 3; ++row)
        for (int l = 0; l < L; ++l) {
          const float x = T[3 * row][l], y = T[3 * row + 1][l];
          T[3 * row][l] = c[l] * x + s[l] * y;
          T[3 * row + 1][l] = c[l] * y - s[l] * x;
        }
    }
    for (int e = 0; e < 12; ++e)
      for (int l = 0; l < L; ++l) {
        M[e][l] = T[e][l];
        frames[(j * 12 + e) * L + l] = T[e][l];
      }
  }
}

// The moving spheres of every lane: x at scratch[k * L + lane] (then y, z after all of x).
ANTIPODE_INLINE void batch_spheres(const KernelArm& a, const float* __restrict frames,
                                   float* __restrict x, float* __restrict y, float* __restrict z) {
  for (int k = 0; k < a.moving; ++k) {
    const int j = a.joint[k];
    float* xk = x + k * L;
    float* yk = y + k * L;
    float* zk = z + k * L;
    if (j < 0) {  // padding: far away
      for (int l = 0; l < L; ++l) xk[l] = yk[l] = zk[l] = 1e6f;
      continue;
    }
    const float* F = frames + std::ptrdiff_t(j) * 12 * L;
    const float lx = a.lx[k], ly = a.ly[k], lz = a.lz[k];
    for (int l = 0; l < L; ++l) {
      xk[l] = F[0 * L + l] * lx + F[1 * L + l] * ly + F[2 * L + l] * lz + F[9 * L + l];
      yk[l] = F[3 * L + l] * lx + F[4 * L + l] * ly + F[5 * L + l] * lz + F[10 * L + l];
      zk[l] = F[6 * L + l] * lx + F[7 * L + l] * ly + F[8 * L + l] * lz + F[11 * L + l];
    }
  }
}

// The bounds of every lane, as batch_spheres() places the spheres (a fixed bound everywhere
// the same).
ANTIPODE_INLINE void batch_bounds(const KernelArm& a, const float* __restrict frames,
                                  float* __restrict x, float* __restrict y, float* __restrict z) {
  for (int b = 0; b < a.bounds; ++b) {
    const int j = a.bound_joint[b];
    const float lx = a.bound_lx[b], ly = a.bound_ly[b], lz = a.bound_lz[b];
    float* xb = x + b * L;
    float* yb = y + b * L;
    float* zb = z + b * L;
    if (j < 0) {
      for (int l = 0; l < L; ++l) xb[l] = lx, yb[l] = ly, zb[l] = lz;
      continue;
    }
    const float* F = frames + std::ptrdiff_t(j) * 12 * L;
    for (int l = 0; l < L; ++l) {
      xb[l] = F[0 * L + l] * lx + F[1 * L + l] * ly + F[2 * L + l] * lz + F[9 * L + l];
      yb[l] = F[3 * L + l] * lx + F[4 * L + l] * ly + F[5 * L + l] * lz + F[10 * L + l];
      zb[l] = F[6 * L + l] * lx + F[7 * L + l] * ly + F[8 * L + l] * lz + F[11 * L + l];
    }
  }
}

// Whether bounds i and j (placed at x, y, z) overlap in any lane.
ANTIPODE_INLINE bool bounds_meet(const KernelArm& a, const float* __restrict x,
                                 const float* __restrict y, const float* __restrict z, int i,
                                 int j) {
  const float* xi = x + i * L;
  const float* yi = y + i * L;
  const float* zi = z + i * L;
  const float* xj = x + j * L;
  const float* yj = y + j * L;
  const float* zj = z + j * L;
  const float reach = a.bound_r[i] + a.bound_r[j];
  std::int32_t any = 0;
  for (int l = 0; l < L; ++l) {
    const float dx = xi[l] - xj[l], dy = yi[l] - yj[l], dz = zi[l] - zj[l];
    any |= std::int32_t(dx * dx + dy * dy + dz * dz <= reach * reach);
  }
  return any != 0;
}

// Whether sphere (x, y, z, r) meets box b in any lane.
ANTIPODE_INLINE bool box_met(const KernelBox& b, const float* __restrict x,
                             const float* __restrict y, const float* __restrict z, float r) {
  std::int32_t any = 0;
  for (int l = 0; l < L; ++l) any |= std::int32_t(gap2(b, x[l], y[l], z[l]) <= r * r);
  return any != 0;
}

// Lanes where sphere k (radius r) meets box b, OR-ed into hit.
ANTIPODE_INLINE void batch_box(const KernelBox& box, const float* __restrict x,
                               const float* __restrict y, const float* __restrict z, float r,
                               std::int32_t* __restrict hit) {
  // The box copied and the lanes' answers into a local array first: written straight into
  // `hit`, GCC also emits a scalar copy of the loop, which the robot's boxes ran.
  const KernelBox b = box;
  alignas(64) std::int32_t touch[L];
  for (int l = 0; l < L; ++l) touch[l] = std::int32_t(gap2(b, x[l], y[l], z[l]) <= r * r);
  for (int l = 0; l < L; ++l) hit[l] |= touch[l];
}

// Lanes where sphere pair (i, j) overlaps - j a moving sphere, or from a.moving on a fixed one
// - OR-ed into hit; their radii from r (the moving spheres) and fr (the fixed ones): a.r and
// a.fr, or the inner radii a.inner and a.f_inner.
ANTIPODE_INLINE void pair_test(const KernelArm& a, const float* __restrict x,
                               const float* __restrict y, const float* __restrict z, int i, int j,
                               const float* __restrict r, const float* __restrict fr,
                               std::int32_t* __restrict hit) {
  const float* xi = x + i * L;
  const float* yi = y + i * L;
  const float* zi = z + i * L;
  if (j < a.moving) {
    const float* xj = x + j * L;
    const float* yj = y + j * L;
    const float* zj = z + j * L;
    const float reach = r[i] + r[j];
    for (int l = 0; l < L; ++l) {
      const float dx = xi[l] - xj[l], dy = yi[l] - yj[l], dz = zi[l] - zj[l];
      hit[l] |= std::int32_t(dx * dx + dy * dy + dz * dz <= reach * reach);
    }
  } else {
    const int f = j - a.moving;
    const float fx = a.fx[f], fy = a.fy[f], fz = a.fz[f], reach = r[i] + fr[f];
    for (int l = 0; l < L; ++l) {
      const float dx = xi[l] - fx, dy = yi[l] - fy, dz = zi[l] - fz;
      hit[l] |= std::int32_t(dx * dx + dy * dy + dz * dz <= reach * reach);
    }
  }
}

ANTIPODE_INLINE std::uint32_t lanes_of(const std::int32_t* hit) {
  std::uint32_t bits = 0;
  for (int l = 0; l < L; ++l) bits |= std::uint32_t(hit[l] != 0) << l;
  return bits;
}

// Moves what one group of tests found into `hit` and, when wanted, into *out as bits by lane;
// clears `found` for the next group.
ANTIPODE_INLINE void take(std::int32_t* __restrict found, std::int32_t* __restrict hit,
                          std::uint32_t* out) {
  if (out != nullptr) *out = lanes_of(found);
  for (int l = 0; l < L; ++l) {
    hit[l] |= found[l];
    found[l] = 0;
  }
}

// Entry i of one of `where`'s arrays (null when nothing is recorded).
ANTIPODE_INLINE std::uint32_t* entry(std::uint32_t* array, int i) {
  return array != nullptr ? array + i : nullptr;
}

// A batch's placed spheres (x, y, z: sphere by sphere, lane by lane) and bounds (bx, by, bz),
// what they touch so far (hit), the scratch of one group (found) and the record (where).
struct Placed {
  const float *x, *y, *z, *bx, *by, *bz;
  std::int32_t* hit;
  std::int32_t* found;
  KernelContacts* where;
  std::int32_t* certain;  // the lanes of a certain contact (null: not looked for)
};

// Whether to look for a certain contact after a group whose record is `out`: only where the
// group touches in some lane. The certain contacts are the same tests with the spheres' inner
// radii (KernelArm), against the boxes' solid parts.
ANTIPODE_INLINE bool look_closer(const Placed& s, const std::uint32_t* out) {
  return s.certain != nullptr && out != nullptr && *out != 0;
}
ANTIPODE_INLINE KernelBox solid_part(const KernelBox& box) {
  KernelBox solid = box;
  for (int i = 0; i < 3; ++i) solid.half[i] = box.solid[i];
  return solid;
}
// Whether spheres i and j (as pair_test() takes them) both have an inner ball.
ANTIPODE_INLINE bool inner_both(const KernelArm& a, int i, int j) {
  return a.inner[i] > 0.0f && (j < a.moving ? a.inner[j] : a.f_inner[j - a.moving]) > 0.0f;
}

// The robot: sphere pairs, then its fixed boxes, a link pair's or a link and box's only where
// their bounds meet.
ANTIPODE_INLINE void robot_loop(const KernelArm& a, const Placed& s) {
  KernelContacts* w = s.where;
  for (int g = 0; g < a.groups; ++g) {
    std::uint32_t* out = entry(w != nullptr ? w->groups : nullptr, g);
    if (a.cull && !bounds_meet(a, s.bx, s.by, s.bz, a.group_a[g], a.group_b[g])) {
      if (out != nullptr) *out = 0;
      continue;
    }
    for (int p = a.group_first[g]; p < a.group_first[g + 1]; ++p)
      pair_test(a, s.x, s.y, s.z, a.pair_a[p], a.pair_b[p], a.r, a.fr, s.found);
    take(s.found, s.hit, out);
    for (int p = a.group_first[g]; look_closer(s, out) && p < a.group_first[g + 1]; ++p)
      if (inner_both(a, a.pair_a[p], a.pair_b[p]))
        pair_test(a, s.x, s.y, s.z, a.pair_a[p], a.pair_b[p], a.inner, a.f_inner, s.certain);
  }
  for (int g = 0; g < a.box_groups; ++g) {
    std::uint32_t* out = entry(w != nullptr ? w->box_groups : nullptr, g);
    const KernelBox& box = a.robot_boxes[a.box_group_box[g]];
    const int b = a.box_group_bound[g];
    if (a.cull && !box_met(box, s.bx + b * L, s.by + b * L, s.bz + b * L, a.bound_r[b])) {
      if (out != nullptr) *out = 0;
      continue;
    }
    for (int p = a.box_group_first[g]; p < a.box_group_first[g + 1]; ++p) {
      const int k = a.box_sphere[p];
      batch_box(box, s.x + k * L, s.y + k * L, s.z + k * L, a.r[k], s.found);
    }
    take(s.found, s.hit, out);
    if (!look_closer(s, out)) continue;
    const KernelBox solid = solid_part(box);
    for (int p = a.box_group_first[g]; p < a.box_group_first[g + 1]; ++p) {
      const int k = a.box_sphere[p];
      if (a.inner[k] > 0.0f)
        batch_box(solid, s.x + k * L, s.y + k * L, s.z + k * L, a.inner[k], s.certain);
    }
  }
}

// The scene's boxes, a link's spheres only where its bound meets the box.
ANTIPODE_INLINE void scene_loop(const KernelArm& a, const KernelBox* boxes, int box_count,
                                const Placed& s) {
  for (int c = 0; c < box_count; ++c)
    for (int b = 0; b < a.moving_bounds; ++b) {
      std::uint32_t* out =
          entry(s.where != nullptr ? s.where->scene_boxes : nullptr, b * box_count + c);
      if (a.cull && !box_met(boxes[c], s.bx + b * L, s.by + b * L, s.bz + b * L, a.bound_r[b])) {
        if (out != nullptr) *out = 0;
        continue;
      }
      for (int k = a.bound_first[b]; k < a.bound_end[b]; ++k)
        batch_box(boxes[c], s.x + k * L, s.y + k * L, s.z + k * L, a.r[k], s.found);
      take(s.found, s.hit, out);
      if (!look_closer(s, out)) continue;
      const KernelBox solid = solid_part(boxes[c]);
      for (int k = a.bound_first[b]; k < a.bound_end[b]; ++k)
        if (a.inner[k] > 0.0f)
          batch_box(solid, s.x + k * L, s.y + k * L, s.z + k * L, a.inner[k], s.certain);
    }
}

// The points (grid null: none), link by link.
ANTIPODE_INLINE void points_loop(const KernelArm& a, const KernelGrid* grid, const Placed& s) {
  for (int b = 0; b < a.moving_bounds; ++b) {
    for (int k = a.bound_first[b]; grid != nullptr && k < a.bound_end[b]; ++k) {
      if (a.points_r[k] < 0.0f) continue;
      std::uint8_t touches[L];
      float r[L];
      for (int l = 0; l < L; ++l) r[l] = a.points_r[k];
      grid_loop(*grid, s.x + k * L, s.y + k * L, s.z + k * L, r, kBatchLanes, touches);
      for (int l = 0; l < L; ++l) s.found[l] |= touches[l];
    }
    take(s.found, s.hit, entry(s.where != nullptr ? s.where->points : nullptr, b));
  }
}

ANTIPODE_INLINE std::uint32_t batch_loop(const KernelArm& a, const KernelBox* boxes, int box_count,
                                         const KernelGrid* grid, const float* q, float* scratch,
                                         KernelContacts* where) {
  float* frames = scratch;
  float* x = frames + std::ptrdiff_t(a.dof) * 12 * L;
  float* y = x + a.moving * L;
  float* z = y + a.moving * L;
  float* bx = z + a.moving * L;
  float* by = bx + a.bounds * L;
  float* bz = by + a.bounds * L;
  batch_kinematics(a, q, frames);
  batch_spheres(a, frames, x, y, z);
  batch_bounds(a, frames, bx, by, bz);
  alignas(64) std::int32_t hit[L] = {};
  alignas(64) std::int32_t found[L] = {};
  alignas(64) std::int32_t certain[L] = {};
  const bool look = where != nullptr && where->certain != nullptr;
  const Placed placed{x, y, z, bx, by, bz, hit, found, where, look ? certain : nullptr};
  robot_loop(a, placed);
  if (where == nullptr && lanes_of(hit) == (std::uint32_t(1) << L) - 1) return lanes_of(hit);
  scene_loop(a, boxes, box_count, placed);
  points_loop(a, grid, placed);
  if (look) *where->certain = lanes_of(certain);
  return lanes_of(hit);
}

ANTIPODE_INLINE void min_shifted_loop(float* __restrict out, const float* __restrict in,
                                      std::ptrdiff_t n, std::ptrdiff_t offset, float add) {
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const float v = add + in[i + offset];
    out[i] = v < out[i] ? v : out[i];
  }
}

// The three builds of each loop.
#define ANTIPODE_BUILDS(name, loop, params, args)                 \
  ANTIPODE_AVX512 auto name##_avx512 params { return loop args; } \
  ANTIPODE_AVX2 auto name##_avx2 params { return loop args; }     \
  auto name##_baseline params { return loop args; }

ANTIPODE_BUILDS(transform, transform_loop,
                (const float* R, const float* t, const float* lx, const float* ly, const float* lz,
                 int n, float* wx, float* wy, float* wz),
                (R, t, lx, ly, lz, n, wx, wy, wz))
ANTIPODE_BUILDS(boxes, boxes_loop,
                (const KernelBox* b, int nb, const float* x, const float* y, const float* z,
                 const float* r, int n, std::uint32_t* bits),
                (b, nb, x, y, z, r, n, bits))
ANTIPODE_BUILDS(overlaps, overlaps_loop,
                (const float* x, const float* y, const float* z, const float* r, int rows,
                 int columns, const std::int32_t* allowed, const std::int32_t* row_begin,
                 const std::int32_t* row_end, std::int32_t* hits),
                (x, y, z, r, rows, columns, allowed, row_begin, row_end, hits))
ANTIPODE_BUILDS(batch, batch_loop,
                (const KernelArm& a, const KernelBox* boxes, int box_count, const KernelGrid* grid,
                 const float* q, float* scratch, KernelContacts* where),
                (a, boxes, box_count, grid, q, scratch, where))
ANTIPODE_BUILDS(min_shifted, min_shifted_loop,
                (float* out, const float* in, std::ptrdiff_t n, std::ptrdiff_t offset, float add),
                (out, in, n, offset, add))
ANTIPODE_BUILDS(grid, grid_loop,
                (const KernelGrid& g, const float* x, const float* y, const float* z,
                 const float* r, int n, std::uint8_t* t),
                (g, x, y, z, r, n, t))

SimdLevel widest_supported() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq"))
    return SimdLevel::kAvx512;
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return SimdLevel::kAvx2;
  return SimdLevel::kBaseline;
}

std::atomic<SimdLevel>& level() {
  static std::atomic<SimdLevel> current{widest_supported()};
  return current;
}

std::atomic<bool>& culling() {
  static std::atomic<bool> on{true};
  return on;
}

}  // namespace

SimdLevel simd_level() { return level().load(std::memory_order_relaxed); }

SimdLevel set_simd_level(SimdLevel wanted) {
  const SimdLevel set = std::min(wanted, widest_supported());
  level().store(set);
  return set;
}

bool sphere_culling() { return culling().load(std::memory_order_relaxed); }

void set_sphere_culling(bool on) { culling().store(on); }

const char* to_string(SimdLevel l) {
  switch (l) {
    case SimdLevel::kAvx512:
      return "AVX-512";
    case SimdLevel::kAvx2:
      return "AVX2";
    case SimdLevel::kBaseline:
      return "baseline";
  }
  return "?";
}

#define ANTIPODE_DISPATCH(name, args) \
  switch (simd_level()) {             \
    case SimdLevel::kAvx512:          \
      return name##_avx512 args;      \
    case SimdLevel::kAvx2:            \
      return name##_avx2 args;        \
    case SimdLevel::kBaseline:        \
      return name##_baseline args;    \
  }

void transform_points(const float* R, const float* t, const float* lx, const float* ly,
                      const float* lz, int n, float* wx, float* wy, float* wz) {
  ANTIPODE_DISPATCH(transform, (R, t, lx, ly, lz, n, wx, wy, wz))
}

void mark_in_boxes(const KernelBox* boxes, int box_count, const float* x, const float* y,
                   const float* z, const float* r, int n, std::uint32_t* bits) {
  ANTIPODE_DISPATCH(boxes, (boxes, box_count, x, y, z, r, n, bits))
}

void mark_overlaps(const float* x, const float* y, const float* z, const float* r, int rows,
                   int columns, const std::int32_t* allowed, const std::int32_t* row_begin,
                   const std::int32_t* row_end, std::int32_t* hits) {
  ANTIPODE_DISPATCH(overlaps, (x, y, z, r, rows, columns, allowed, row_begin, row_end, hits))
}

void mark_near_points(const KernelGrid& grid, const float* x, const float* y, const float* z,
                      const float* r, int n, std::uint8_t* touches){
    ANTIPODE_DISPATCH(grid, (grid, x, y, z, r, n, touches))}

std::uint32_t
    mark_batch(const KernelArm& arm, const KernelBox* boxes, int box_count, const KernelGrid* grid,
               const float* q, float* scratch, KernelContacts* where) {
  ANTIPODE_DISPATCH(batch, (arm, boxes, box_count, grid, q, scratch, where))
  return 0;
}

void min_shifted(float* out, const float* in, std::ptrdiff_t n, std::ptrdiff_t offset,
                 float add){ANTIPODE_DISPATCH(min_shifted, (out, in, n, offset, add))}

std::size_t batch_scratch_floats(const KernelArm& arm) {
  return std::size_t(arm.dof * 12 + 3 * arm.moving + 3 * arm.bounds) * kBatchLanes;
}

}  // namespace antipode::collision
