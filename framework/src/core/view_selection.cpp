#include "antipode/core/view_selection.hpp"

#include <algorithm>
#include <string>

#include "antipode/core/error.hpp"

namespace antipode {

Cloud points_of_views(const Cloud& cloud, const std::vector<int>& views,
                      std::vector<std::int32_t>* new_index) {
  if (views.empty()) throw Error("view selection: no view given");
  // A cloud without view origins is one view (view 0).
  const std::size_t count = std::max<std::size_t>(1, cloud.view_origins_m.size());
  for (auto it = views.begin(); it != views.end(); ++it) {
    const int v = *it;
    if (v < 0 || v >= 32 || static_cast<std::size_t>(v) >= count) {
      throw Error("view selection: view " + std::to_string(v) + " is not in the cloud, which has " +
                  std::to_string(count) + " view(s)");
    }
    if (std::find(views.begin(), it, v) != it) {
      throw Error("view selection: view " + std::to_string(v) + " is listed twice");
    }
  }
  Cloud out;
  out.frame = cloud.frame;
  for (const int v : views) {
    if (static_cast<std::size_t>(v) < cloud.view_origins_m.size()) {
      out.view_origins_m.push_back(cloud.view_origins_m[static_cast<std::size_t>(v)]);
    }
  }
  if (new_index != nullptr) new_index->assign(cloud.size(), -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::uint32_t mask = cloud.view_masks.empty() ? 1u : cloud.view_masks[i];
    std::uint32_t kept = 0;
    for (std::size_t k = 0; k < views.size(); ++k) {
      if (((mask >> static_cast<unsigned>(views[k])) & 1u) != 0) kept |= 1u << k;
    }
    if (kept == 0) continue;
    if (new_index != nullptr) (*new_index)[i] = static_cast<std::int32_t>(out.points_m.size());
    out.points_m.push_back(cloud.points_m[i]);
    if (!cloud.normals.empty()) out.normals.push_back(cloud.normals[i]);
    if (!cloud.view_origins_m.empty()) out.view_masks.push_back(kept);
  }
  return out;
}

}  // namespace antipode
