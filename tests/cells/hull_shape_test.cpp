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

// A random cloud of `n` points in a 10 cm cube: its hull has fewer vertices, not a multiple
// of four as a rule.
TriangleMesh random_points(int n, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f);
  TriangleMesh mesh;
  for (int i = 0; i < n; ++i) mesh.vertices.emplace_back(u(random), u(random), u(random));
  return mesh;
}

TEST(HullShape, AnswersAsBulletDoesBitForBit) {
  std::mt19937 random(7);
  std::normal_distribution<float> g(0.0f, 1.0f);
  for (const int n : {4, 5, 9, 37, 200, 1000}) {
    const HullShape shape(random_points(n, std::uint32_t(n)), 0.001);
    ASSERT_GT(shape.getNumPoints(), 3);
    for (int k = 0; k < 20000; ++k) {
      const btVector3 d(g(random), g(random), g(random));
      ASSERT_TRUE(
          same_bits(shape.localGetSupportingVertexWithoutMargin(d), bullet_support(shape, d)))
          << n << " points, direction " << d.x() << " " << d.y() << " " << d.z();
    }
  }
}

TEST(HullShape, TiesGoToTheFirstVertexAsInBullet) {
  // A box's faces: along an axis four vertices tie, along a face diagonal two.
  const HullShape shape(box_mesh(Eigen::Vector3f(0.02f, 0.03f, 0.04f)), 0.001);
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        const btVector3 d{btScalar(x), btScalar(y), btScalar(z)};
        EXPECT_TRUE(
            same_bits(shape.localGetSupportingVertexWithoutMargin(d), bullet_support(shape, d)))
            << x << " " << y << " " << z;
      }
    }
  }
}

TEST(HullShape, ADirectionWithoutADotProductGivesTheFirstVertex) {
  const HullShape shape(random_points(50, 3), 0.001);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(shape.farthest_vertex(btVector3(nan, 0, 0)), -1);
  EXPECT_EQ(shape.farthest_vertex(btVector3(nan, 0, 0), false), -1);
  EXPECT_TRUE(same_bits(shape.localGetSupportingVertexWithoutMargin(btVector3(nan, 1, 0)),
                        shape.getUnscaledPoints()[0]));
}

TEST(HullShape, IsAPolyhedronToBulletsDispatch) {
  const HullShape shape(random_points(50, 5), 0.002);
  EXPECT_TRUE(shape.isConvex());
  EXPECT_TRUE(shape.isPolyhedral());
  EXPECT_NE(shape.getConvexPolyhedron(), nullptr);
  EXPECT_FLOAT_EQ(shape.getMargin(), 0.002f);
  // The non-virtual support Bullet's GJK calls reaches this shape's own.
  const btVector3 d(0.3f, -0.5f, 0.8f);
  EXPECT_TRUE(same_bits(shape.localGetSupportVertexWithoutMarginNonVirtual(d),
                        shape.localGetSupportingVertexWithoutMargin(d)));
}

TEST(HullShape, AMeshWithoutVerticesIsAnError) {
  EXPECT_THROW(HullShape(TriangleMesh{}, 0.001), Error);
}

}  // namespace
}  // namespace antipode::cells
