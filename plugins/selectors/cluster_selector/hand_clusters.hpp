#pragma once
// Clusters of similar hands and their mean grasp (paper section 5.1: "hypotheses that are
// nearby each other and that are roughly aligned in orientation are grouped together").

#include <cstddef>
#include <vector>

#include "antipode/core/hand.hpp"

namespace antipode::selectors {

struct ClusterOptions {
  double distance_m = 0.02;  ///< largest distance between palm-face centres
  double angle_deg = 20.0;   ///< largest angle between approaches and between closing axes
};

/// True when `a` and `b` belong together: on the same object (Hand::object), palm-face
/// centres within the distance, approach
/// directions within the angle, and closing directions within the angle up to their sign
/// (a parallel gripper turned half a turn about its approach is the same grasp).
bool similar(const Hand& a, const Hand& b, const ClusterOptions& options);

/// Greedy clusters: in the order of `order` (indices into `hands`, best first), each hand
/// not yet taken seeds a cluster of itself and every later untaken hand similar to it.
/// Returns the clusters as index lists, seed first. Deterministic.
std::vector<std::vector<std::size_t>> cluster_hands(const std::vector<Hand>& hands,
                                                    const std::vector<std::size_t>& order,
                                                    const ClusterOptions& options);

/// The mean grasp of `members` (indices into `hands`, the first being the seed): the mean
/// palm-face centre, the rotation nearest the mean of the members' rotations (each turned
/// half a turn about its approach when its closing direction opposes the seed's), the
/// largest width, the sum of the scores (a grasp many nearby hands agree on ranks first),
/// the seed's sample index and label; no closing points.
Hand mean_hand(const std::vector<Hand>& hands, const std::vector<std::size_t>& members);

}  // namespace antipode::selectors
