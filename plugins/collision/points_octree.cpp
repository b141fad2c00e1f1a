#include "points_octree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>

#include "sphere_kernels.hpp"

namespace antipode::collision {
namespace {

octomap::OcTreeKey unpacked(std::uint64_t k) {
  return octomap::OcTreeKey(octomap::key_type(k & 0xffff), octomap::key_type(k >> 16 & 0xffff),
                            octomap::key_type(k >> 32 & 0xffff));
}

constexpr std::uint64_t kNoKey = ~std::uint64_t(0);

#define ANTIPODE_INLINE inline __attribute__((always_inline))

// The packed leaf keys of the `n` points of `xyz` (x, y, z per point), as octomap's
// coordToKeyChecked computes them - floor(coordinate * (1 / resolution)) + 2^15 on each axis,
// in double - or kNoKey for a point it leaves out (outside the key range, or not finite).
// Written once and compiled for two targets: with AVX2 (and its SSE4.1) the floor is one
// instruction, without it a sequence of bit operations.
ANTIPODE_INLINE void keys_loop(const float* __restrict xyz, std::size_t n, double factor,
                               std::uint64_t* __restrict keys) {
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::floor(double(xyz[3 * k]) * factor);
    const double y = std::floor(double(xyz[3 * k + 1]) * factor);
    const double z = std::floor(double(xyz[3 * k + 2]) * factor);
    // A comparison with NaN is false: a point that is not finite is left out.
    const bool inside = (x >= -32768.0) & (x < 32768.0) & (y >= -32768.0) & (y < 32768.0) &
                        (z >= -32768.0) & (z < 32768.0);
    const auto key = [inside](double v) {
      return std::uint64_t(std::uint32_t(std::int32_t(inside ? v : 0.0) + 32768));
    };
    const std::uint64_t packed_key = key(x) | key(y) << 16 | key(z) << 32;
    keys[k] = inside ? packed_key : kNoKey;
  }
}

__attribute__((target("avx2"))) void keys_avx2(const float* xyz, std::size_t n, double factor,
                                               std::uint64_t* keys) {
  keys_loop(xyz, n, factor, keys);
}

void keys_baseline(const float* xyz, std::size_t n, double factor, std::uint64_t* keys) {
  keys_loop(xyz, n, factor, keys);
}

std::vector<std::uint64_t> leaf_keys(const octomap::OcTree& tree,
                                     const std::vector<Eigen::Vector3f>& points_m) {
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "points are packed x, y, z");
  std::vector<std::uint64_t> keys(points_m.size());
  const double factor = 1.0 / tree.getResolution();  // octomap's resolution_factor
  const float* xyz = points_m.empty() ? nullptr : points_m.front().data();
  const bool avx2 = simd_level() != SimdLevel::kBaseline;
  (avx2 ? keys_avx2 : keys_baseline)(xyz, points_m.size(), factor, keys.data());
  return keys;
}

using LeafHits = std::vector<std::pair<std::uint64_t, std::uint32_t>>;

// Hits per leaf key, counted in blocks of 8 x 8 x 8 leaves: a hash map finds a point's
// block only when the block differs from the last point's (a capture lists neighbouring
// points together: the 457,000 points of a two-view capture change leaf about every 3
// points, and a block spans 8 leaves each way), and the block's array counts its leaves
// (saturating: a leaf's log-odds stop changing after a few hits). Block by block in the order of
// their keys, then leaf by leaf: the order depends only on the leaves. Nothing when the points
// spread over more than `max_blocks` blocks (a sparse cloud, a fine resolution): the arrays would
// outweigh the points.
std::optional<LeafHits> hits_by_block(const std::vector<std::uint64_t>& keys,
                                      std::size_t max_blocks) {
  constexpr std::size_t kCells = 512;
  // A leaf key (16 bits per axis, packed 16 apart) splits into its block (the upper 13 bits
  // of each axis) and its cell in the block (the lower 3).
  const auto block_key = [](std::uint64_t key) {
    return key >> 3 &
           (std::uint64_t(0x1fff) | std::uint64_t(0x1fff) << 16 | std::uint64_t(0x1fff) << 32);
  };
  const auto cell = [](std::uint64_t key) {
    return std::size_t(key & 7) | std::size_t(key >> 16 & 7) << 3 | std::size_t(key >> 32 & 7) << 6;
  };
  std::unordered_map<std::uint64_t, std::size_t> block_at;  // block key -> its first count
  std::vector<std::uint64_t> blocks;
  std::vector<std::uint16_t> counts;
  std::uint64_t last_block = kNoKey;
  std::size_t base = 0;
  for (const std::uint64_t k : keys) {
    if (k == kNoKey) continue;
    const std::uint64_t b = block_key(k);
    if (b != last_block) {
      const auto [it, added] = block_at.try_emplace(b, counts.size());
      if (added) {
        if (blocks.size() == max_blocks) return std::nullopt;
        blocks.push_back(b);
        counts.resize(counts.size() + kCells, 0);
      }
      last_block = b;
      base = it->second;
    }
    std::uint16_t& count = counts[base + cell(k)];
    count = std::uint16_t(count + (count < 0xffff ? 1 : 0));
  }
  std::sort(blocks.begin(), blocks.end());
  LeafHits hits;
  for (const std::uint64_t b : blocks) {
    const std::size_t first = block_at[b];
    for (std::size_t c = 0; c < kCells; ++c) {
      if (counts[first + c] == 0) continue;
      const std::uint64_t key = b << 3 | std::uint64_t(c & 7) | std::uint64_t(c >> 3 & 7) << 16 |
                                std::uint64_t(c >> 6 & 7) << 32;
      hits.emplace_back(key, counts[first + c]);
    }
  }
  return hits;
}

// Hits per leaf key with one hash map entry per leaf (runs of one key counted before they
// reach it), in key order: for clouds too sparse for blocks.
LeafHits hits_by_leaf(const std::vector<std::uint64_t>& keys) {
  std::unordered_map<std::uint64_t, std::uint32_t> hits;
  std::uint64_t run_key = kNoKey;
  std::uint32_t run = 0;
  for (const std::uint64_t k : keys) {
    if (k == kNoKey) continue;
    if (run > 0 && k == run_key) {
      ++run;
      continue;
    }
    if (run > 0) hits[run_key] += run;
    run_key = k;
    run = 1;
  }
  if (run > 0) hits[run_key] += run;
  LeafHits sorted(hits.begin(), hits.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

LeafHits leaf_hits(const octomap::OcTree& tree, const std::vector<Eigen::Vector3f>& points_m) {
  const std::vector<std::uint64_t> keys = leaf_keys(tree, points_m);
  // At most 32 bytes of block counts per point (a block's are 1 KB).
  if (auto hits = hits_by_block(keys, keys.size() / 32 + 256)) return std::move(*hits);
  return hits_by_leaf(keys);
}

// The log-odds of a leaf after `hits` hits from zero: each hit added in float and the sum
// clamped, as OccupancyOcTreeBase::updateNodeLogOdds does, and no hit once at the maximum.
float log_odds_after(std::uint32_t hits, float hit, float max) {
  float value = 0.0f;
  for (std::uint32_t i = 0; i < hits && value < max; ++i) value = std::min(value + hit, max);
  return value;
}

}  // namespace

std::shared_ptr<octomap::OcTree> points_octree(const std::vector<Eigen::Vector3f>& points_m,
                                               double resolution_m) {
  auto tree = std::make_shared<octomap::OcTree>(resolution_m);
  const float hit = tree->getProbHitLog(), max = tree->getClampingThresMaxLog();
  for (const auto& [key, hits] : leaf_hits(*tree, points_m))
    tree->updateNode(unpacked(key), log_odds_after(hits, hit, max), /*lazy_eval=*/true);
  tree->updateInnerOccupancy();
  tree->prune();
  return tree;
}

std::shared_ptr<octomap::OcTree> points_octree_point_by_point(
    const std::vector<Eigen::Vector3f>& points_m, double resolution_m) {
  auto tree = std::make_shared<octomap::OcTree>(resolution_m);
  for (const Eigen::Vector3f& p : points_m)
    if (p.allFinite()) tree->updateNode(octomap::point3d(p.x(), p.y(), p.z()), true);
  return tree;
}

}  // namespace antipode::collision
