#pragma once
// The octree of observed points that FCL checks the arm against: the tree octomap makes when
// every finite point is inserted as a hit (OcTree::updateNode(point, true)), node for node
// and value for value, built with one tree descent per occupied leaf instead of per point.
//
// The points' leaf keys are computed as octomap computes them and counted in blocks of 8 x 8 x 8
// leaves (a capture lists neighbouring points together, so a hash map is asked for a point's block
// only when it changes); each leaf then gets the log-odds its hits sum to, clamped after every hit
// as octomap clamps it, and the inner nodes are updated and pruned once at the end: a capture's
// 460,800 points at 1 cm about 8 times faster than point by point (collision_bench
// --benchmark_filter=PointsOctree, both side by side).
//
// Units: metres. Points outside octomap's key range, or not finite, are left out, as
// updateNode leaves them out. Threads: a call uses only its arguments.

#include <memory>
#include <vector>

#include <octomap/OcTree.h>
#include <Eigen/Core>

namespace antipode::collision {

/// The octree of `points_m` at `resolution_m` (octomap's default sensor model).
std::shared_ptr<octomap::OcTree> points_octree(const std::vector<Eigen::Vector3f>& points_m,
                                               double resolution_m);

/// The same tree built as octomap builds it, one updateNode per point: the reference the
/// tests and the benchmark compare with.
std::shared_ptr<octomap::OcTree> points_octree_point_by_point(
    const std::vector<Eigen::Vector3f>& points_m, double resolution_m);

}  // namespace antipode::collision
