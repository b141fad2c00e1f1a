#pragma once
// Internal to the geometry area: Euclidean clustering (region growing by distance).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace antipode::geometry {

/// Splits `members` (indices into `points`) into clusters: two members belong to the same
/// cluster when a chain of members joins them with no step longer than `tolerance_m`.
/// Clusters come in the order of their smallest member index, members in increasing order,
/// so the result depends only on the input (not on thread counts or the index's layout).
/// "Closer than `tolerance_m`" is decided as PointIndex::radius_search decides it, so the
/// clusters are those region growing with its ball queries finds. A member that is not
/// finite, or lies more than 1e15 tolerances from the origin, is a cluster of its own.
/// `tolerance_m` must be positive and finite.
std::vector<std::vector<std::int32_t>> euclidean_clusters(
    const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& members,
    float tolerance_m);

}  // namespace antipode::geometry
