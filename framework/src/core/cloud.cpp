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

Eigen::Vector3f Cloud::direction_to_sensors(std::size_t i) const {
  const Eigen::Vector3f& p = points_m[i];
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  const std::uint32_t mask = view_masks.empty() ? 1u : view_masks[i];
  for (std::size_t v = 0; v < view_origins_m.size() && v < 32; ++v) {
    if ((mask >> v) & 1u) sum += (view_origins_m[v] - p).normalized();
  }
  const float norm = sum.norm();
  return norm > 1e-6f ? (sum / norm).eval() : Eigen::Vector3f::Zero();
}

}  // namespace antipode
