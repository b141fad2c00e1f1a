#pragma once
// The objects and poses of the isolation benchmark.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace antipode::cli {

/// One test object: how the cell's `object` parameter names it (a procedural shape or a
/// mesh in a folder, as a YAML flow mapping without its pose) and whether the gripper can
/// hold it at all (an object without a width in the gripper's range is counted apart).
struct BenchObject {
  std::string name;
  std::string spec_yaml;  ///< e.g. "shape: sphere, size_m: [0.042]" or "mesh: 025_mug, folder: /d"
  bool graspable = true;
};

/// The objects of `which`: "procedural" reads `procedural_file` (a list of shapes with their
/// sizes and graspable widths, scenes/objects/procedural_test_set.yaml), anything else is a
/// folder of meshes (subfolders holding visual.obj, or NAME.obj files), taken in name order,
/// whose graspable width is the smallest extent of the mesh's bounding box. Objects whose
/// graspable width lies outside [min_width_m, max_width_m] are not graspable.
/// Throws antipode::Error naming the file or folder when it cannot be read or holds none.
std::vector<BenchObject> bench_objects(const std::string& which, const std::string& procedural_file,
                                       double min_width_m, double max_width_m);

/// The orientation (roll, pitch, yaw in radians) of systematic pose `k` of `poses`: even
/// poses stand upright, odd ones lie on their side (a quarter turn about x); the yaw steps
/// by a full turn over `poses`, so poses 0..poses-1 spread around the object. The object is
/// then set down on the table and left to settle.
Eigen::Vector3d pose_rpy(int k, int poses);

}  // namespace antipode::cli
