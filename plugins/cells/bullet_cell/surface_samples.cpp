#include "surface_samples.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace antipode::cells {
namespace {

bool inside(const Eigen::Vector3d& p, const Eigen::Vector3d& half) {
  return (p.array().abs() <= half.array()).all();
}

// The corners reordered so that the first has the widest angle (it faces the longest edge):
// the grid along the two edges from it is then sheared by at most 30 degrees.
std::array<Eigen::Vector3d, 3> widest_corner_first(const Eigen::Vector3d& a,
                                                   const Eigen::Vector3d& b,
                                                   const Eigen::Vector3d& c) {
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc >= ab && bc >= ca) return {a, b, c};
  if (ca >= ab) return {b, c, a};
  return {c, a, b};
}

}  // namespace

void sample_mesh_near(const TriangleMesh& mesh, const Eigen::Isometry3d& X_BaseMesh,
                      const Eigen::Isometry3d& X_BaseRegion, const Eigen::Vector3d& half_extents_m,
                      double spacing_m, std::size_t max_points, std::vector<Eigen::Vector3f>& out) {
  const Eigen::Isometry3d X_RegionMesh = X_BaseRegion.inverse() * X_BaseMesh;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    if (out.size() >= max_points) return;
    const auto [a, b, c] = widest_corner_first(X_RegionMesh * mesh.vertices[t[0]].cast<double>(),
                                               X_RegionMesh * mesh.vertices[t[1]].cast<double>(),
                                               X_RegionMesh * mesh.vertices[t[2]].cast<double>());
    const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    if ((lo.array() > half_extents_m.array()).any() || (hi.array() < -half_extents_m.array()).any())
      continue;
    // Points a + (b - a) i / nb + (c - a) j / nc for i / nb + j / nc <= 1, the two edges from
    // the widest corner cut into steps of at most spacing_m: about one point per spacing_m
    // squared, however long and thin the triangle (a box wall's); one no wider than the
    // spacing (a scanned mesh's) gives its centroid.
    if ((c - b).norm() <= spacing_m) {  // the longest edge, facing the widest corner
      const Eigen::Vector3d centroid = (a + b + c) / 3.0;
      if (inside(centroid, half_extents_m)) out.push_back((X_BaseRegion * centroid).cast<float>());
      continue;
    }
    const int nb = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing_m)));
    const int nc = std::max(1, static_cast<int>(std::ceil((c - a).norm() / spacing_m)));
    for (int i = 0; i <= nb; ++i) {
      for (int j = 0; double(i) / nb + double(j) / nc <= 1.0 + 1e-9; ++j) {
        const Eigen::Vector3d p = a + (b - a) * (double(i) / nb) + (c - a) * (double(j) / nc);
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
