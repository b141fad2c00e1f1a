#include "antipode/core/cloud.hpp"

#include <cmath>

#include "antipode/core/error.hpp"

namespace antipode {

void Cloud::validate() const {
  const std::size_t n = points_m.size();
  if (!normals.empty() && normals.size() != n) {
    throw Error("cloud: " + std::to_string(normals.size()) + " normals for " + std::to_string(n) +
                " points");
  }
  if (!view_masks.empty() && view_masks.size() != n) {
    throw Error("cloud: " + std::to_string(view_masks.size()) + " view masks for " +
                std::to_string(n) + " points");
  }
  if (view_origins_m.size() > 32) throw Error("cloud: more than 32 views");
  const std::uint32_t known_views =
      view_origins_m.size() == 32 ? 0xffffffffu : (1u << view_origins_m.size()) - 1u;
  for (std::size_t i = 0; i < view_masks.size(); ++i) {
    if ((view_masks[i] & ~known_views) != 0) {
      throw Error("cloud: point " + std::to_string(i) + " names a view with no origin");
    }
  }
  for (std::size_t i = 0; i < normals.size(); ++i) {
    if (std::abs(normals[i].norm() - 1.0f) > 1e-3f) {
      throw Error("cloud: normal " + std::to_string(i) + " is not unit length");
    }
  }
}

}  // namespace antipode
