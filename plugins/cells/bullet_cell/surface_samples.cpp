#include "surface_samples.hpp"

#include <algorithm>
#include <cmath>

namespace antipode::cells {
namespace {

bool inside(const Eigen::Vector3d& p, const Eigen::Vector3d& half) {
  return (p.array().abs() <= half.array()).all();
}

}  // namespace

void sample_mesh_near(const TriangleMesh& mesh, const Eigen::Isometry3d& X_BaseMesh,
                      const Eigen::Isometry3d& X_BaseRegion, const Eigen::Vector3d& half_extents_m,
                      double spacing_m, std::size_t max_points, std::vector<Eigen::Vector3f>& out) {
  const Eigen::Isometry3d X_RegionMesh = X_BaseRegion.inverse() * X_BaseMesh;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if (out.size() >= max_points) return;
    const Eigen::Vector3d a = X_RegionMesh * mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = X_RegionMesh * mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = X_RegionMesh * mesh.vertices[t[2]].cast<double>();
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    if ((lo.array() > half_extents_m.array()).any() || (hi.array() < -half_extents_m.array()).any())
      continue;
    // Points a + (b - a) i / n + (c - a) j / n for i + j <= n: n steps along the longest
    // edge, so no two neighbours are more than spacing_m apart.
    const double longest_m = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
    const int n = std::max(1, static_cast<int>(std::ceil(longest_m / spacing_m)));
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Eigen::Vector3d p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
        if (!inside(p, half_extents_m)) continue;
        if (out.size() >= max_points) return;
        out.push_back((X_BaseRegion * p).cast<float>());
      }
    }
  }
}

std::vector<Eigen::Vector3f> surface_points_near(const PhysicsWorld& world,
                                                 const Eigen::Isometry3d& X_BaseRegion,
                                                 const Eigen::Vector3d& half_extents_m,
                                                 double spacing_m, std::size_t max_points) {
  std::vector<Eigen::Vector3f> out;
  for (const PhysicsWorld::Visual& visual : world.visuals())
    sample_mesh_near(*visual.mesh, visual.pose, X_BaseRegion, half_extents_m, spacing_m, max_points,
                     out);
  return out;
}

}  // namespace antipode::cells
