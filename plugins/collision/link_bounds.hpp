#pragma once
// One bounding sphere per link around the link's spheres, and sphere pairs grouped by the
// links they lie between: what lets the batched sphere test skip the tests of two links, or
// of a link and a box, that are apart in every configuration of a batch (sphere_kernels.hpp,
// KernelArm). Bounds apart means every pair of spheres inside them apart, so skipping changes
// no answer.
//
// Frames and units: a bound is in the frame of its link's spheres - the joint frame a moving
// link hangs from, the base frame for a fixed link - in metres. Threads: plain data and pure
// functions.

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace antipode::collision {

/// The bounds of a robot's links, the moving links' first.
struct LinkBounds {
  std::vector<int> of_link;              ///< per link, its bound (-1 for a link without spheres)
  std::vector<int> link;                 ///< per bound, its link
  int moving = 0;                        ///< bounds [0, moving) are the moving links'
  std::vector<std::int32_t> joint;       ///< per bound, its link's joint (-1: fixed)
  std::vector<std::int32_t> first, end;  ///< per bound, its spheres [first, end)
  std::vector<float> x, y, z, radius;    ///< per bound, its centre and radius
};

/// The bounds of the links that own spheres: sphere k (centre x, y, z, radius r) belongs to
/// link owner[k] (-1: padding, in no bound), a link's spheres next to each other; link i moves
/// with joint link_joint[i] (-1: fixed). Each bound is centred in the box of its spheres'
/// centres and reaches `margin_m` past the farthest sphere, so that float rounding of the
/// placed bound and spheres never takes a sphere outside it.
LinkBounds bound_links(const std::vector<int>& owner, const std::vector<int>& link_joint,
                       const std::vector<float>& x, const std::vector<float>& y,
                       const std::vector<float>& z, const std::vector<float>& r, double margin_m);

/// Pairs grouped by a key: group g has key (a[g], b[g]) and holds pairs [first[g],
/// first[g + 1]).
struct PairGroups {
  std::vector<std::int32_t> a, b, first;
};

/// Reorders the pairs (pa[p], pb[p]) so that those of one key(p) come together, each group in
/// the order its pairs had, and returns the groups.
PairGroups group_by_key(std::vector<std::int32_t>& pa, std::vector<std::int32_t>& pb,
                        const std::function<std::pair<int, int>(std::size_t)>& key);

}  // namespace antipode::collision
