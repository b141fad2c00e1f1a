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
/// "Closer than `tolerance_m`" is nanoflann's leaf test, the one PointIndex::radius_search
/// applies to the points it visits: the squared differences summed in single precision in x,
/// y, z order, less than tolerance_m * tolerance_m. A member that is not finite, or lies
/// more than 5e14 tolerances from the origin along an axis, is a cluster of its own.
/// `tolerance_m` must be in [1e-15, 1e15] m (its square a normal float), else Error.
std::vector<std::vector<std::int32_t>> euclidean_clusters(
    const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& members,
    float tolerance_m);

}  // namespace antipode::geometry
