#include "points_octree.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace antipode::collision {
namespace {

std::uint64_t packed(const octomap::OcTreeKey& key) {
  return std::uint64_t(key[0]) | std::uint64_t(key[1]) << 16 | std::uint64_t(key[2]) << 32;
}

octomap::OcTreeKey unpacked(std::uint64_t k) {
  return octomap::OcTreeKey(octomap::key_type(k & 0xffff), octomap::key_type(k >> 16 & 0xffff),
                            octomap::key_type(k >> 32 & 0xffff));
}

// Hits per leaf key, in key order.
std::vector<std::pair<std::uint64_t, std::uint32_t>> leaf_hits(
    const octomap::OcTree& tree, const std::vector<Eigen::Vector3f>& points_m) {
  std::unordered_map<std::uint64_t, std::uint32_t> hits;
  hits.reserve(points_m.size() / 16 + 16);
  std::uint64_t run_key = 0;
  std::uint32_t run = 0;
  octomap::OcTreeKey key;
  for (const Eigen::Vector3f& p : points_m) {
    if (!p.allFinite() || !tree.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key))
      continue;
    const std::uint64_t k = packed(key);
    if (run > 0 && k == run_key) {
      ++run;
      continue;
    }
    if (run > 0) hits[run_key] += run;
    run_key = k;
    run = 1;
  }
  if (run > 0) hits[run_key] += run;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted(hits.begin(), hits.end());
  std::sort(sorted.begin(), sorted.end());
  return sorted;
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
