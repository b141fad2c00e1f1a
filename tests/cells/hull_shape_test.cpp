#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "hull_shape.hpp"
#include "primitive_meshes.hpp"

namespace antipode::cells {
namespace {

// Bullet's own answer for the same hull: the btConvexHullShape the HullShape is.
btVector3 bullet_support(const HullShape& shape, const btVector3& direction) {
  return shape.btConvexHullShape::localGetSupportingVertexWithoutMargin(direction);
}

bool same_bits(const btVector3& a, const btVector3& b) {
  return a.x() == b.x() && a.y() == b.y() && a.z() == b.z() &&
         std::signbit(a.x()) == std::signbit(b.x()) && std::signbit(a.y()) == std::signbit(b.y()) &&
         std::signbit(a.z()) == std::signbit(b.z());
}

// A random cloud of `n` points in a 10 cm cube: its hull has fewer vertices, as a rule not a
// multiple of either scan width (four or eight).
TriangleMesh random_points(int n, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f);
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) mesh.vertices.emplace_back(u(random), u(random), u(random));
  return mesh;
}

// What farthest_vertex() picks, eight (`wide`) or four at a time, as a support point.
btVector3 vertex(const HullShape& shape, const btVector3& direction, bool wide) {
  const int i = shape.farthest_vertex(direction, wide);
  return shape.getUnscaledPoints()[i < 0 ? 0 : i];
}

TEST(HullShape, AnswersAsBulletDoesBitForBit) {
  std::mt19937 random(7);
  std::normal_distribution<float> g(0.0f, 1.0f);
  for (const int n : {4, 5, 9, 37, 200, 1000}) {
    const HullShape shape(random_points(n, std::uint32_t(n)), 0.001);
    ASSERT_GT(shape.getNumPoints(), 3);
    for (int k = 0; k < 20000; ++k) {
      const btVector3 d(g(random), g(random), g(random));
      const btVector3 expected = bullet_support(shape, d);
      ASSERT_TRUE(same_bits(shape.localGetSupportingVertexWithoutMargin(d), expected))
          << n << " points, direction " << d.x() << " " << d.y() << " " << d.z();
      for (const bool wide : {true, false})
        ASSERT_TRUE(same_bits(vertex(shape, d, wide), expected)) << n << " points, wide " << wide;
    }
  }
}

TEST(HullShape, TiesGoToTheFirstVertexAsInBullet) {
  // A box: along an axis four vertices tie, along a face diagonal two. A 32-sided cylinder:
  // along its axis a cap's 32 vertices tie, more than one pass of either scan takes.
  const HullShape box(box_mesh(Eigen::Vector3f(0.02f, 0.03f, 0.04f)), 0.001);
  const HullShape cylinder(cylinder_mesh(0.03f, 0.1f, 32), 0.001);
  ASSERT_GE(cylinder.getNumPoints(), 64);
  for (const HullShape* shape : {&box, &cylinder}) {
    for (int x = -1; x <= 1; ++x) {
      for (int y = -1; y <= 1; ++y) {
        for (int z = -1; z <= 1; ++z) {
          const btVector3 d{btScalar(x), btScalar(y), btScalar(z)};
          const btVector3 expected = bullet_support(*shape, d);
          EXPECT_TRUE(same_bits(shape->localGetSupportingVertexWithoutMargin(d), expected))
              << shape->getNumPoints() << " vertices, " << x << " " << y << " " << z;
          for (const bool wide : {true, false})
            EXPECT_TRUE(same_bits(vertex(*shape, d, wide), expected))
                << shape->getNumPoints() << " vertices, " << x << " " << y << " " << z << ", wide "
                << wide;
        }
      }
    }
  }
}

TEST(HullShape, WithoutADotProductAboveMinusFltMaxTheFirstVertex) {
  // Bullet's running maximum starts at -FLT_MAX (SIMD_INFINITY in the float build): a dot
  // product of -FLT_MAX or less, or NaN, never wins, and convexHullSupport() then takes
  // vertex 0. A box beyond x = 1.9, seen along -x, scaled so that its nearest vertices' dot
  // products are exactly -FLT_MAX (the others' overflow to -infinity): no vertex wins.
  TriangleMesh mesh = box_mesh(Eigen::Vector3f(0.02f, 0.03f, 0.04f));
  for (auto& v : mesh.vertices) v.x() += 2.0f;  // x_min > 1: FLT_MAX / x_min is finite
  const HullShape shape(mesh, 0.001);
  const btVector3* points = shape.getUnscaledPoints();
  float x_min = points[0].x();
  for (int i = 1; i < shape.getNumPoints(); ++i) x_min = std::min(x_min, points[i].x());
  ASSERT_GT(x_min, 1.0f);
  const float fmax = std::numeric_limits<float>::max();
  float scale = fmax / x_min;  // nudged until x_min * scale is the largest product <= FLT_MAX
  for (int i = 0; i < 64 && x_min * scale > fmax; ++i) scale = std::nextafter(scale, 0.0f);
  for (int i = 0; i < 64 && x_min * std::nextafter(scale, fmax) <= fmax; ++i)
    scale = std::nextafter(scale, fmax);
  ASSERT_EQ(x_min * -scale, -fmax);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const btVector3& d : {btVector3(-scale, 0, 0), btVector3(nan, 0, 0)}) {
    btScalar dot = 0;
    EXPECT_EQ(d.maxDot(points, shape.getNumPoints(), dot), -1);  // Bullet's own rule
    for (const bool wide : {true, false}) EXPECT_EQ(shape.farthest_vertex(d, wide), -1) << wide;
    EXPECT_TRUE(same_bits(shape.localGetSupportingVertexWithoutMargin(d), points[0]));
  }
  // A little less far along -x, the nearest vertices win again, the first of them.
  const btVector3 less(-std::nextafter(scale, 0.0f), 0, 0);
  btScalar dot = 0;
  const long expected = less.maxDot(points, shape.getNumPoints(), dot);
  ASSERT_GE(expected, 0);
  for (const bool wide : {true, false}) EXPECT_EQ(shape.farthest_vertex(less, wide), expected);
}

TEST(HullShape, IsAPolyhedronToBulletsDispatch) {
  const HullShape shape(random_points(50, 5), 0.002);
  EXPECT_TRUE(shape.isConvex());
  EXPECT_TRUE(shape.isPolyhedral());
  EXPECT_NE(shape.getConvexPolyhedron(), nullptr);
  EXPECT_FLOAT_EQ(shape.getMargin(), 0.002f);
  // The non-virtual support Bullet's GJK calls scans a CONVEX_HULL_SHAPE_PROXYTYPE itself;
  // for this type it calls the shape's own (whose answers equal Bullet's, so the type is what
  // tells them apart).
#if defined(__x86_64__)
  EXPECT_EQ(shape.getShapeType(), CUSTOM_POLYHEDRAL_SHAPE_TYPE);
#endif
  const btVector3 d(0.3f, -0.5f, 0.8f);
  EXPECT_TRUE(same_bits(shape.localGetSupportVertexWithoutMarginNonVirtual(d),
                        shape.localGetSupportingVertexWithoutMargin(d)));
}

TEST(HullShape, AMeshWithoutVerticesIsAnError) {
  EXPECT_THROW(HullShape(TriangleMesh{}, 0.001), Error);
}

}  // namespace
}  // namespace antipode::cells
