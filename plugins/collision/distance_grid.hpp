#pragma once
// How far the observed points' octree cells are from any place near them: a Euclidean
// distance transform of the occupied cells, for checking spheres against a point cloud in
// constant time per sphere.
//
// The occupied space is the octree's (ArmCollisionWorld::set_points): the cubes of
// `resolution_m`, keyed as octomap keys its leaves, that hold a point. The grid's cells are
// those cubes (cubes of 2^k of them when the points span more than 16 million), and each
// stores the distance D between its centre and the nearest occupied cell's centre. A point p
// whose cell's value is D is at least D - sqrt(3) h from every occupied cube (each centre is
// within sqrt(3) h / 2 of the points of its cell), so a sphere of radius r about p is clear
// of them when D - sqrt(3) h > r: the test never calls a touching sphere clear. Distances
// matter only up to `reach_m` (the largest sphere); the grid reaches that far past the
// occupied cubes, and beyond it the distance to their bounding box stands in.
//
// The transform is separable (Felzenszwalb and Huttenlocher, Theory of Computing 8, 2012):
// the squared distance along x in each row, then the least of d^2 plus that over rows up to
// `reach` away along y, then along z. The windowed passes are whole-grid sweeps of one shifted
// minimum each (sphere_kernels.hpp), exact within `reach` and never above the truth beyond;
// the exact lower-envelope transform (divisions per cell), tried first, took 20 ms for the
// 1.5 million cells of a capture of the cell's table at 1 cm, and 145 ms at 5 mm cells.
//
// Units: metres, in the points' frame. Threads: immutable after construction.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sphere_kernels.hpp"

namespace antipode::collision {

class DistanceGrid {
 public:
  /// An empty grid: every sphere is clear.
  DistanceGrid() = default;
  /// Throws antipode::Error for a resolution or reach that is not positive and finite.
  DistanceGrid(const std::vector<Eigen::Vector3f>& points_m, double resolution_m, double reach_m);

  bool empty() const { return clear_m_.empty(); }
  /// Grid cells (for reports and tests).
  std::size_t cells() const { return clear_m_.size(); }

  /// For each of `n` spheres (centres x, y, z, radii r): 1 in `touches` when it may touch an
  /// occupied cube, 0 when it is clear of them. A sphere with a negative radius is clear.
  void mark_touching(const float* x, const float* y, const float* z, const float* r, int n,
                     std::uint8_t* touches) const;

  /// What the kernels read (sphere_kernels.hpp); only for a grid that is not empty.
  KernelGrid kernel() const;

 private:
  float h_ = 0.0f;
  Eigen::Vector3i origin_ = Eigen::Vector3i::Zero();  // the first cell's index (multiples of h)
  Eigen::Vector3i size_ = Eigen::Vector3i::Zero();
  Eigen::Vector3f box_min_ = Eigen::Vector3f::Zero();  // the occupied cubes' bounding box
  Eigen::Vector3f box_max_ = Eigen::Vector3f::Zero();
  std::vector<float> clear_m_;  // D - sqrt(3) h per cell, x fastest
};

}  // namespace antipode::collision
