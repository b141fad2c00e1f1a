#pragma once
// Internal to the geometry area: copying the points a predicate keeps, with their normals
// and view masks; where a cloud's sensors are.

#include "antipode/core/cloud.hpp"

namespace antipode::geometry {

/// The cloud made of the points whose index i keep_index(i) accepts, in their order.
template <typename KeepIndex>
Cloud select_indices(const Cloud& cloud, KeepIndex keep_index) {
  Cloud out;
  out.frame = cloud.frame;
  out.view_origins_m = cloud.view_origins_m;
  out.points_m.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!keep_index(i)) continue;
    out.points_m.push_back(cloud.points_m[i]);
    if (cloud.has_normals()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.view_masks.empty()) out.view_masks.push_back(cloud.view_masks[i]);
  }
  return out;
}

/// The cloud made of the points for which keep(point) is true, in their order.
template <typename Keep>
Cloud select_points(const Cloud& cloud, Keep keep) {
  return select_indices(cloud, [&](std::size_t i) { return keep(cloud.points_m[i]); });
}

/// Where the sensors are: the mean of the view origins (the origin without any).
inline Eigen::Vector3f sensor_position(const Cloud& cloud) {
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (const auto& origin : cloud.view_origins_m) sum += origin;
  return cloud.view_origins_m.empty()
             ? sum
             : (sum / static_cast<float>(cloud.view_origins_m.size())).eval();
}

}  // namespace antipode::geometry
