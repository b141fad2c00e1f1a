#pragma once
/// @file
/// A point cloud as antipode passes it between stages.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace antipode {

/// Points in one frame, with optional normals and, per point, which views saw it.
///
/// Invariants (checked by validate()):
/// - `normals` is empty or has one entry per point; normals are unit length.
/// - `view_masks` is empty or has one entry per point; bit v set means view v saw the point
///   (a raw single-view capture sets exactly one bit; a voxelised two-view cloud may set
///   both). At most 32 views.
/// - `view_origins_m[v]` is the sensor origin of view v in `frame`.
struct Cloud {
  std::vector<Eigen::Vector3f> points_m;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::uint32_t> view_masks;
  std::vector<Eigen::Vector3f> view_origins_m;
  std::string frame = "base";

  std::size_t size() const { return points_m.size(); }
  bool empty() const { return points_m.empty(); }
  bool has_normals() const { return !normals.empty(); }

  /// The unit direction from point `i` towards the sensors that saw it: the normalised sum
  /// of the unit directions to the origins whose bit its view mask sets (no masks: view 0).
  /// Zero when there are no view origins or the directions cancel out.
  Eigen::Vector3f direction_to_sensors(std::size_t i) const;

  /// Throws antipode::Error describing the first broken invariant.
  void validate() const;
};

/// How clouds travel between behaviour-tree nodes: shared, never copied, never modified.
using CloudPtr = std::shared_ptr<const Cloud>;

}  // namespace antipode
