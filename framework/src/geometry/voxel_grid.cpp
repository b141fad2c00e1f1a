#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "antipode/core/error.hpp"
#include "antipode/geometry/preprocess.hpp"

namespace antipode {
namespace {

constexpr int kBitsPerAxis = 21;
constexpr std::int64_t kHalfRange = std::int64_t{1} << (kBitsPerAxis - 1);

// Voxel coordinates packed as z | y | x, each shifted to be non-negative.
std::uint64_t voxel_key(const Eigen::Vector3f& p, double inverse_size) {
  std::uint64_t key = 0;
  for (int axis = 2; axis >= 0; --axis) {
    const auto cell = static_cast<std::int64_t>(std::floor(p[axis] * inverse_size));
    if (cell < -kHalfRange || cell >= kHalfRange) {
      throw Error("voxel grid: point (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                  ", " + std::to_string(p.z()) + ") is too far from the origin for the voxel size");
    }
    key = (key << kBitsPerAxis) | static_cast<std::uint64_t>(cell + kHalfRange);
  }
  return key;
}

// Merges the points order[begin, end) of `cloud` (one voxel) and appends the result to `out`.
void merge_voxel(const Cloud& cloud,
                 const std::vector<std::pair<std::uint64_t, std::uint32_t>>& order,
                 std::size_t begin, std::size_t end, Cloud& out) {
  Eigen::Vector3d sum_point = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_normal = Eigen::Vector3d::Zero();
  std::uint32_t mask = 0;
  for (std::size_t k = begin; k < end; ++k) {
    const std::uint32_t i = order[k].second;
    sum_point += cloud.points_m[i].cast<double>();
    if (cloud.has_normals()) sum_normal += cloud.normals[i].cast<double>();
    if (!cloud.view_masks.empty()) mask |= cloud.view_masks[i];
  }
  out.points_m.push_back((sum_point / static_cast<double>(end - begin)).cast<float>());
  if (cloud.has_normals()) {
    const double norm = sum_normal.norm();
    out.normals.push_back(norm > 1e-6 ? (sum_normal / norm).cast<float>().eval()
                                      : cloud.normals[order[begin].second]);
  }
  if (!cloud.view_masks.empty()) out.view_masks.push_back(mask);
}

}  // namespace

Cloud voxelize(const Cloud& cloud, float voxel_size_m) {
  if (!(voxel_size_m > 0.0f) || !std::isfinite(voxel_size_m)) {
    throw Error("voxel grid: voxel size must be positive, got " + std::to_string(voxel_size_m));
  }
  const double inverse_size = 1.0 / static_cast<double>(voxel_size_m);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    order[i] = {voxel_key(cloud.points_m[i], inverse_size), static_cast<std::uint32_t>(i)};
  }
  std::sort(order.begin(), order.end());
  Cloud out;
  out.frame = cloud.frame;
  out.view_origins_m = cloud.view_origins_m;
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() && order[end].first == order[begin].first) ++end;
    merge_voxel(cloud, order, begin, end, out);
    begin = end;
  }
  return out;
}

}  // namespace antipode
