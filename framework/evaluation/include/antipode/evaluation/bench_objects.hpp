#pragma once
// The objects and poses of the isolation benchmark.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace antipode::evaluation {

/// The gripper's range in the paper's setting (Baxter's gripper, docs/cell.md): an object
/// whose narrowest horizontal extent as it lies is outside it cannot be held from above, and
/// finding no grasp on it is the right answer. The isolation bench counts such attempts
/// apart; the clutter bench tells such objects apart among those left in the box.
constexpr double kMinGraspableWidthM = 0.03;
constexpr double kMaxGraspableWidthM = 0.07;

/// One test object: how the cell's `object` parameter names it (a procedural shape or a
/// mesh in a folder, as a YAML flow mapping without its pose) and whether the gripper can
/// hold it at all (an object without a width in the gripper's range is counted apart).
struct BenchObject {
  std::string name;
  std::string spec_yaml;  ///< e.g. "shape: sphere, size_m: [0.042]" or "mesh: 025_mug, folder: /d"
  /// The width a gripper must span: listed for procedural shapes (docs/cell.md), the
  /// smallest extent of the bounding box for meshes.
  double width_m = 0.0;
  /// A mesh's vertices (metres), to judge each pose; null for procedural shapes.
  std::shared_ptr<const std::vector<Eigen::Vector3d>> vertices;

  /// Whether a gripper spanning [min_width_m, max_width_m] can hold the object in pose `k`
  /// of `poses` as it lies on the table: for a mesh, some horizontal direction across it
  /// must have an extent in that range (a box lying flat 14 cm wide both ways cannot be
  /// held from above, and from the side one finger would have to pass under it); for a
  /// procedural shape, its listed width.
  bool graspable_in_pose(int k, int poses, double min_width_m, double max_width_m) const;
};

/// The objects of `which`: "procedural" reads `procedural_file` (a list of shapes with their
/// sizes and graspable widths, scenes/objects/procedural_test_set.yaml), anything else is a
/// folder of meshes (subfolders holding visual.obj, or NAME.obj files), taken in name order.
/// Throws antipode::Error naming the file or folder when it cannot be read or holds none.
std::vector<BenchObject> bench_objects(const std::string& which,
                                       const std::string& procedural_file);

/// The orientation (roll, pitch, yaw in radians) of systematic pose `k` of `poses`: even
/// poses stand upright, odd ones lie on their side (a quarter turn about x); the yaw steps
/// by a full turn over `poses`, so poses 0..poses-1 spread around the object. The object is
/// then set down on the table and left to settle.
Eigen::Vector3d pose_rpy(int k, int poses);

}  // namespace antipode::evaluation
