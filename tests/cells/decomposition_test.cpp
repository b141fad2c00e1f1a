#include <gtest/gtest.h>

#include <LinearMath/btConvexHullComputer.h>

#include "convex_decomposition.hpp"
#include "primitive_meshes.hpp"

namespace antipode::cells {
namespace {

// True when `p` lies inside the convex hull `hull` (within `tolerance_m`).
bool inside(const TriangleMesh& hull, const Eigen::Vector3f& p, float tolerance_m = 1e-4f) {
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3f a = hull.vertices[std::size_t(t[0])];
    const Eigen::Vector3f n = (hull.vertices[std::size_t(t[1])] - a)
                                  .cross(hull.vertices[std::size_t(t[2])] - a)
                                  .normalized();
    if (n.dot(p - a) > tolerance_m) return false;
  }
  return true;
}

bool inside_any(const std::vector<TriangleMesh>& hulls, const Eigen::Vector3f& p) {
  for (const auto& hull : hulls)
    if (inside(hull, p)) return true;
  return false;
}

// A cup: outer radius 4 cm, walls 5 mm, bottom 5 mm, 8 cm high, open at the top.
TriangleMesh cup() {
  return revolution_mesh({{0.0f, 0.0f},
                          {0.04f, 0.0f},
                          {0.04f, 0.08f},
                          {0.035f, 0.08f},
                          {0.035f, 0.005f},
                          {0.0f, 0.005f}},
                         48);
}

TEST(ConvexDecomposition, AConvexMeshIsOneHull) {
  const auto hulls = convex_decomposition(box_mesh({0.02f, 0.03f, 0.05f}));
  ASSERT_EQ(hulls.size(), 1u);
  EXPECT_NEAR(hulls[0].volume(), 0.04 * 0.06 * 0.1, 1e-7);
}

TEST(ConvexDecomposition, ACupKeepsItsCavityAndItsWalls) {
  const auto hulls = convex_decomposition(cup());
  EXPECT_GT(hulls.size(), 8u);
  // The cavity is free: its axis, and points 1 cm inside the wall, at every height.
  for (float z = 0.015f; z < 0.08f; z += 0.01f) {
    EXPECT_FALSE(inside_any(hulls, {0.0f, 0.0f, z})) << "cavity axis at z = " << z;
    for (int k = 0; k < 16; ++k) {
      const float a = float(k) * 0.3927f;
      EXPECT_FALSE(inside_any(hulls, {0.024f * std::cos(a), 0.024f * std::sin(a), z}))
          << "1 cm inside the wall at angle " << a << ", z = " << z;
    }
  }
  // The walls and the bottom are solid: the middle of the wall all round, the bottom's middle.
  for (float z = 0.01f; z < 0.075f; z += 0.01f)
    for (int k = 0; k < 32; ++k) {
      const float a = float(k) * 0.19635f;
      EXPECT_TRUE(inside_any(hulls, {0.0375f * std::cos(a), 0.0375f * std::sin(a), z}))
          << "in the wall at angle " << a << ", z = " << z;
    }
  EXPECT_TRUE(inside_any(hulls, {0.0f, 0.0f, 0.0025f}));
  // Nothing sticks out: every hull lies within the cup's outer cylinder (1 mm for facets).
  for (const auto& hull : hulls)
    for (const auto& v : hull.vertices) {
      EXPECT_LE(v.head<2>().norm(), 0.0405f);
      EXPECT_GE(v.z(), -1e-4f);
      EXPECT_LE(v.z(), 0.0801f);
    }
}

TEST(ConvexDecomposition, IsDeterministic) {
  const auto a = convex_decomposition(cup()), b = convex_decomposition(cup());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].vertices, b[i].vertices);
}

TEST(ConvexDecomposition, AFlatMeshHasNoVolume) {
  TriangleMesh sheet;
  sheet.vertices = {{0, 0, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}};
  sheet.triangles = {{0, 1, 2}};
  EXPECT_TRUE(convex_decomposition(sheet).empty());
}

}  // namespace
}  // namespace antipode::cells
