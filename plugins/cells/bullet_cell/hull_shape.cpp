#include "hull_shape.hpp"

#include <cstdint>
#include <limits>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "antipode/core/error.hpp"

namespace antipode::cells {

namespace {

// `n` coordinates of `points` (x: 0, y: 1, z: 2), padded to a multiple of eight with NaN,
// whose dot products never win.
std::vector<float> padded_coordinates(const btVector3* points, int n, int axis) {
  std::vector<float> out((static_cast<std::size_t>(n) + 7) / 8 * 8,
                         std::numeric_limits<float>::quiet_NaN());
  for (int i = 0; i < n; ++i) out[std::size_t(i)] = points[i][axis];
  return out;
}

}  // namespace

HullShape::HullShape(const TriangleMesh& mesh, double margin_m) {
  if (mesh.vertices.empty()) throw Error("a collision hull has no vertex");
  for (const auto& v : mesh.vertices) addPoint(btVector3(v.x(), v.y(), v.z()), false);
  recalcLocalAabb();
  optimizeConvexHull();
  setMargin(btScalar(margin_m));
  initializePolyhedralFeatures();
  x_ = padded_coordinates(getUnscaledPoints(), getNumPoints(), 0);
  y_ = padded_coordinates(getUnscaledPoints(), getNumPoints(), 1);
  z_ = padded_coordinates(getUnscaledPoints(), getNumPoints(), 2);
#if defined(__x86_64__)
  // Bullet's non-virtual support dispatch scans a CONVEX_HULL_SHAPE_PROXYTYPE itself and
  // calls the virtual localGetSupportingVertexWithoutMargin() for this type.
  m_shapeType = CUSTOM_POLYHEDRAL_SHAPE_TYPE;
#endif
}

#if defined(__x86_64__)
namespace {

// The first greatest of `lanes` (dot, index) pairs, by dot then by index; -1 when no lane
// found a vertex.
int first_greatest(const float* best, const std::int32_t* index, int lanes) {
  int found = -1;
  float found_dot = std::numeric_limits<float>::lowest();
  for (int lane = 0; lane < lanes; ++lane) {
    if (index[lane] < 0) continue;
    if (best[lane] > found_dot || (best[lane] == found_dot && index[lane] < found)) {
      found_dot = best[lane];
      found = index[lane];
    }
  }
  return found;
}

// Per lane, the first greatest dot product of the vertices 4k + lane with (dx, dy, dz):
// (x dx + y dy) + z dz, as btVector3::dot(), each product rounded on its own. NaN dot
// products (the padding) never win.
int farthest_sse2(const float* x, const float* y, const float* z, std::size_t padded, float dx,
                  float dy, float dz) {
  const __m128 vx = _mm_set1_ps(dx), vy = _mm_set1_ps(dy), vz = _mm_set1_ps(dz);
  __m128 best = _mm_set1_ps(std::numeric_limits<float>::lowest());
  __m128i best_index = _mm_set1_epi32(-1);
  __m128i index = _mm_setr_epi32(0, 1, 2, 3);
  const __m128i step = _mm_set1_epi32(4);
  for (std::size_t k = 0; k < padded; k += 4) {
    const __m128 xy =
        _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(x + k), vx), _mm_mul_ps(_mm_loadu_ps(y + k), vy));
    const __m128 dot = _mm_add_ps(xy, _mm_mul_ps(_mm_loadu_ps(z + k), vz));
    const __m128 greater = _mm_cmpgt_ps(dot, best);
    best = _mm_or_ps(_mm_and_ps(greater, dot), _mm_andnot_ps(greater, best));
    const __m128i take = _mm_castps_si128(greater);
    best_index = _mm_or_si128(_mm_and_si128(take, index), _mm_andnot_si128(take, best_index));
    index = _mm_add_epi32(index, step);
  }
  alignas(16) float lane_best[4];
  alignas(16) std::int32_t lane_index[4];
  _mm_store_ps(lane_best, best);
  _mm_store_si128(reinterpret_cast<__m128i*>(lane_index), best_index);
  return first_greatest(lane_best, lane_index, 4);
}

// The dot products of vertices k to k + 7 with (vx, vy, vz), rounded as farthest_sse2()'s.
__attribute__((target("avx2"))) inline __m256 dots8(const float* x, const float* y, const float* z,
                                                    std::size_t k, __m256 vx, __m256 vy,
                                                    __m256 vz) {
  const __m256 xy = _mm256_add_ps(_mm256_mul_ps(_mm256_loadu_ps(x + k), vx),
                                  _mm256_mul_ps(_mm256_loadu_ps(y + k), vy));
  return _mm256_add_ps(xy, _mm256_mul_ps(_mm256_loadu_ps(z + k), vz));
}

// The same, eight vertices at a time (AVX2 without FMA: the same roundings), in two passes
// that carry no blend from one step to the next: the greatest dot product (two running
// maxima), then the first vertex whose dot product equals it. NaN dot products (the padding)
// never count: _mm256_max_ps returns its second operand, the running maximum, for them.
__attribute__((target("avx2"))) int farthest_avx2(const float* x, const float* y, const float* z,
                                                  std::size_t padded, float dx, float dy,
                                                  float dz) {
  const __m256 vx = _mm256_set1_ps(dx), vy = _mm256_set1_ps(dy), vz = _mm256_set1_ps(dz);
  const float lowest = std::numeric_limits<float>::lowest();
  __m256 best0 = _mm256_set1_ps(lowest), best1 = best0;
  std::size_t k = 0;
  for (; k + 16 <= padded; k += 16) {
    best0 = _mm256_max_ps(dots8(x, y, z, k, vx, vy, vz), best0);
    best1 = _mm256_max_ps(dots8(x, y, z, k + 8, vx, vy, vz), best1);
  }
  if (k < padded) best0 = _mm256_max_ps(dots8(x, y, z, k, vx, vy, vz), best0);
  alignas(32) float lanes[8];
  _mm256_store_ps(lanes, _mm256_max_ps(best0, best1));
  float greatest = lowest;
  for (const float lane : lanes) greatest = lane > greatest ? lane : greatest;
  if (!(greatest > lowest)) return -1;  // as btVector3::maxDot(): none above -FLT_MAX
  const __m256 target = _mm256_set1_ps(greatest);
  for (k = 0; k < padded; k += 8) {
    const int equal =
        _mm256_movemask_ps(_mm256_cmp_ps(dots8(x, y, z, k, vx, vy, vz), target, _CMP_EQ_OQ));
    if (equal != 0) return static_cast<int>(k) + __builtin_ctz(static_cast<unsigned>(equal));
  }
  return -1;  // not reached: the greatest dot product is one of them
}

}  // namespace
#endif

int HullShape::farthest_vertex(const btVector3& direction, bool wide) const {
  const float dx = direction.x(), dy = direction.y(), dz = direction.z();
  const std::size_t padded = x_.size();
#if defined(__x86_64__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (wide && avx2) return farthest_avx2(x_.data(), y_.data(), z_.data(), padded, dx, dy, dz);
  return farthest_sse2(x_.data(), y_.data(), z_.data(), padded, dx, dy, dz);
#else
  (void)wide;
  int found = -1;
  float found_dot = std::numeric_limits<float>::lowest();
  for (std::size_t i = 0; i < padded; ++i) {
    const float dot = (x_[i] * dx + y_[i] * dy) + z_[i] * dz;
    if (dot > found_dot) {
      found_dot = dot;
      found = static_cast<int>(i);
    }
  }
  return found;
#endif
}

btVector3 HullShape::localGetSupportingVertexWithoutMargin(const btVector3& direction) const {
#if defined(__x86_64__)
  // As Bullet's convexHullSupport(): the direction scaled, the vertex scaled back.
  const btVector3& scaling = getLocalScalingNV();
  const int found = farthest_vertex(direction * scaling);
  return getUnscaledPoints()[found < 0 ? 0 : found] * scaling;
#else
  return btConvexHullShape::localGetSupportingVertexWithoutMargin(direction);
#endif
}

}  // namespace antipode::cells
