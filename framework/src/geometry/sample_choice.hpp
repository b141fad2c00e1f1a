#pragma once
// Internal to the geometry area: which cloud points a search samples, and from where they
// were seen.

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"

namespace antipode::geometry {

/// `count` distinct indices of `candidates`' entries, uniformly at random (a partial
/// Fisher-Yates shuffle driven by `random`), or all of them in order when there are no more
/// than `count`.
std::vector<std::int32_t> choose_samples(std::vector<std::int32_t> candidates, std::size_t count,
                                         RandomStream random);

/// Unit direction from point `index` towards the sensors that saw it (the normalised sum of
/// the unit directions to the origins of the views in its mask). Clouds without masks count
/// as seen by view 0; without origins, from (0, 0, 0), or from the direction away from
/// `outward_from` when it is set. Zero if the directions cancel out.
Eigen::Vector3f toward_viewer(const Cloud& cloud, std::size_t index,
                              const std::optional<Eigen::Vector3f>& outward_from);

}  // namespace antipode::geometry
