#pragma once
// Internal to the geometry area: copying the points a predicate keeps, with their normals
// and view masks.

#include "antipode/core/cloud.hpp"

namespace antipode::geometry {

/// The cloud made of the points for which keep(point) is true, in their order.
template <typename Keep>
Cloud select_points(const Cloud& cloud, Keep keep) {
  Cloud out;
  out.frame = cloud.frame;
  out.view_origins_m = cloud.view_origins_m;
  out.points_m.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!keep(cloud.points_m[i])) continue;
    out.points_m.push_back(cloud.points_m[i]);
    if (cloud.has_normals()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.view_masks.empty()) out.view_masks.push_back(cloud.view_masks[i]);
  }
  return out;
}

}  // namespace antipode::geometry
