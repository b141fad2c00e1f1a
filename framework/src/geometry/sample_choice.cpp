#include "sample_choice.hpp"

namespace antipode::geometry {

std::vector<std::int32_t> choose_samples(std::vector<std::int32_t> indices, std::size_t count,
                                         RandomStream random) {
  const std::size_t size = indices.size();
  if (count >= size) return indices;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t j = i + static_cast<std::size_t>(random.below(size - i));
    std::swap(indices[i], indices[j]);
  }
  indices.resize(count);
  return indices;
}

Eigen::Vector3f toward_viewer(const Cloud& cloud, std::size_t index,
                              const std::optional<Eigen::Vector3f>& outward_from) {
  const Eigen::Vector3f& p = cloud.points_m[index];
  if (cloud.view_origins_m.empty()) {
    const Eigen::Vector3f away = outward_from ? Eigen::Vector3f(p - *outward_from) : Eigen::Vector3f(-p);
    return away.normalized();
  }
  const std::uint32_t mask = cloud.view_masks.empty() ? 1u : cloud.view_masks[index];
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (std::size_t v = 0; v < cloud.view_origins_m.size() && v < 32; ++v) {
    if ((mask >> v) & 1u) sum += (cloud.view_origins_m[v] - p).normalized();
  }
  const float norm = sum.norm();
  return norm > 1e-6f ? (sum / norm).eval() : Eigen::Vector3f::Zero();
}

}  // namespace antipode::geometry
