#pragma once
// A triangle mesh in metres: what the renderer casts rays at and collision hulls are made of.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace antipode::cells {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3i> triangles;  ///< counter-clockwise seen from outside

  bool empty() const { return triangles.empty(); }
  /// Enclosed volume (m^3) of a closed, outward-oriented mesh.
  double volume() const;
  /// Centre of the enclosed volume (the vertex mean when the volume is ~0).
  Eigen::Vector3d volume_centroid() const;
  Eigen::AlignedBox3f bounds() const;
  void transform(const Eigen::Affine3f& transform);
  /// Appends `other`'s triangles.
  void append(const TriangleMesh& other);
};

/// The pieces of `mesh` that share no vertex (a convex decomposition stored as one file).
std::vector<TriangleMesh> connected_pieces(const TriangleMesh& mesh);

}  // namespace antipode::cells
