// Region growing over a KD-tree of the members: each unvisited member starts a cluster, and
// a breadth-first walk adds every member within the tolerance of one already in it. This is
// PCL's EuclideanClusterExtraction; it is written here over the project's nanoflann index
// (point_index.hpp: ball queries about 1.7x faster than PCL's FLANN tree on table_mug.pcd),
// which also keeps PCL's point types out of the geometry code.
#include "euclidean_clusters.hpp"

#include <algorithm>

#include "antipode/geometry/point_index.hpp"

namespace antipode::geometry {

std::vector<std::vector<std::int32_t>> euclidean_clusters(
    const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& members,
    float tolerance_m) {
  std::vector<std::int32_t> sorted = members;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Eigen::Vector3f> subset;
  subset.reserve(sorted.size());
  for (const std::int32_t i : sorted) subset.push_back(points[static_cast<std::size_t>(i)]);
  const PointIndex index(subset);
  std::vector<char> taken(subset.size(), 0);
  std::vector<std::int32_t> near;
  std::vector<std::vector<std::int32_t>> clusters;
  for (std::size_t seed = 0; seed < subset.size(); ++seed) {
    if (taken[seed]) continue;
    std::vector<std::int32_t> cluster{static_cast<std::int32_t>(seed)};
    taken[seed] = 1;
    for (std::size_t next = 0; next < cluster.size(); ++next) {
      index.radius_search(subset[static_cast<std::size_t>(cluster[next])], tolerance_m, near);
      for (const std::int32_t j : near) {
        if (taken[static_cast<std::size_t>(j)]) continue;
        taken[static_cast<std::size_t>(j)] = 1;
        cluster.push_back(j);
      }
    }
    for (std::int32_t& j : cluster) j = sorted[static_cast<std::size_t>(j)];
    std::sort(cluster.begin(), cluster.end());
    clusters.push_back(std::move(cluster));
  }
  return clusters;
}

}  // namespace antipode::geometry
