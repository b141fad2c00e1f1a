#pragma once
// Approximate convex decomposition of an object's visual mesh, so that what the physics
// touches is what the sensors see.
//
// The convex decompositions shipped with mesh sets are often too coarse for grasping: the
// YCB mug's collision.stl is two hulls that fill its cavity, the banana is one hull that
// fills its bend, the drill two that fill the gap under its handle. The sensor sees the
// visual mesh, so hands are planned into space the physics holds solid. No Debian package
// provides V-HACD or a similar decomposition, hence this one.
//
// The algorithm: voxelise the mesh's surface, flood the outside from the grid's border, and
// take the rest as the solid (holes in a scan narrower than a voxel do not leak). Then split
// the solid recursively, always the piece whose convex hull exceeds its volume the most, by
// the axis-aligned plane (three positions on each axis) that leaves the least hull volume
// unexplained, separating disconnected parts as they appear. Each final piece becomes the
// hull of the mesh's surface points in its voxels and of the corners it shares with
// neighbouring interior voxels, so pieces meet along their cuts without gaps inside the
// solid (near the surface, gaps are under a voxel).

#include <vector>

#include "triangle_mesh.hpp"

namespace antipode::cells {

struct DecompositionOptions {
  int resolution = 32;  ///< voxels along the mesh's longest side (for the splitting decisions)
  /// A piece is convex enough when its hull exceeds its volume by at most this share of its
  /// hull's volume (so thin pieces are judged by their shape, not their size) ...
  double max_concavity = 0.1;
  /// ... or by at most this share of the whole solid's hull volume.
  double min_concavity = 0.0005;
  int max_pieces = 64;
  /// Vertices of a piece's hull at most (spread over it by farthest-point sampling).
  int max_hull_vertices = 128;
};

/// Convex pieces (each a closed hull mesh) covering the solid bounded by `mesh`, in the
/// mesh's frame. Deterministic. Returns the hull of the whole mesh when it is convex enough,
/// and an empty list for a mesh without volume.
std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options = {});

}  // namespace antipode::cells
