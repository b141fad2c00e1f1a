#pragma once
// A convex hull for Bullet whose support mapping scans eight vertices at a time.

#include <vector>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include "triangle_mesh.hpp"

namespace antipode::cells {

/// The convex hull of a mesh's vertices (as btConvexHullShape::optimizeConvexHull() makes
/// it), with polyhedral features for contact clipping, answering support queries - the
/// vertex farthest along a direction, which GJK and EPA ask for at every step of every
/// contact - eight vertices at a time with AVX2 where the CPU has it, else four with SSE2,
/// instead of one at a time.
///
/// Why by hand: Debian's Bullet is built without BT_USE_SSE_IN_API, so its support mapping
/// is a scalar loop over the hull's vertices (up to 128 per hull of a decomposed mesh), and
/// that loop was most of a mesh object's physics (docs/results.md, Cell).
///
/// The answers are Bullet's, bit for bit: the same dot products, computed in the same order
/// without fused multiply-adds, and the first vertex whose dot product is greatest and above
/// -FLT_MAX wins, as in btVector3::maxDot(); without one, vertex 0, as Bullet's
/// convexHullSupport(). On x86-64 the shape reports CUSTOM_POLYHEDRAL_SHAPE_TYPE, so that
/// Bullet's non-virtual support dispatch, which scans a btConvexHullShape itself, calls this
/// one; it is convex and polyhedral to Bullet's collision dispatch as a btConvexHullShape is
/// (a world saved to a .bullet file would not load it back). Elsewhere it is Bullet's shape.
/// Bullet's own scan is the reference in `hull_shape_test`.
///
/// The vertices are copied when the shape is built: add no point and do not optimise the
/// hull again afterwards (btConvexHullShape's addPoint() and optimizeConvexHull() would leave
/// the copies stale). Lengths in the mesh's units (metres); not thread-safe to build, const
/// queries are.
class HullShape final : public btConvexHullShape {
 public:
  /// The hull of `mesh`'s vertices with collision margin `margin_m`. The mesh must have a
  /// vertex.
  HullShape(const TriangleMesh& mesh, double margin_m);

  btVector3 localGetSupportingVertexWithoutMargin(const btVector3& direction) const override;

  const char* getName() const override { return "antipode HullShape"; }

  /// The index (into getUnscaledPoints()) of the first vertex of greatest dot product with
  /// `direction`; -1 when no dot product is a number greater than -FLT_MAX. `wide`: eight at
  /// a time where the CPU has AVX2 (false: four, as on a CPU without it).
  int farthest_vertex(const btVector3& direction, bool wide = true) const;

 private:
  // The hull's vertices by coordinate, padded to a multiple of eight with NaN (whose dot
  // products never win).
  std::vector<float> x_, y_, z_;
};

}  // namespace antipode::cells
