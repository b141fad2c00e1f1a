#include <gtest/gtest.h>

#include <cmath>

#include "primitive_meshes.hpp"
#include "surface_samples.hpp"

namespace antipode::cells {
namespace {

// The distance from `p` to the surface of the axis-aligned box of `half` at the origin, for
// a point on or inside it: how far it is from the nearest face.
double off_the_faces_m(const Eigen::Vector3d& p, const Eigen::Vector3d& half) {
  return (half - p.cwiseAbs()).minCoeff();
}

TEST(SurfaceSamples, PointsLieOnTheMeshInsideTheRegionAndCoverIt) {
  // A 10 x 6 x 4 cm box moved to (1, 2, 3); the region: the half of it with x above its
  // centre, in a frame turned 90 degrees about z (the region's half-sides along its axes).
  const Eigen::Vector3d half(0.05, 0.03, 0.02);
  const TriangleMesh box = box_mesh(half.cast<float>());
  const Eigen::Isometry3d X_BaseMesh(Eigen::Translation3d(1.0, 2.0, 3.0));
  Eigen::Isometry3d X_BaseRegion = X_BaseMesh * Eigen::Translation3d(0.05, 0.0, 0.0) *
                                   Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d region_half(0.1, 0.05, 0.1);  // region x = base y, region y = base x
  std::vector<Eigen::Vector3f> points;
  sample_mesh_near(box, X_BaseMesh, X_BaseRegion, region_half, 0.002, 100000, points);
  ASSERT_FALSE(points.empty());
  for (const Eigen::Vector3f& point : points) {
    const Eigen::Vector3d in_mesh = X_BaseMesh.inverse() * point.cast<double>();
    EXPECT_LT(off_the_faces_m(in_mesh, half), 1e-6) << "on a face";
    EXPECT_GE(in_mesh.x(), -1e-6) << "inside the region: the box's half with x >= 0";
  }
  // The half box's surface: the +x face (6 x 4 cm) and half of the four others, 112 cm^2;
  // a grid 2 mm apart along the triangles' edges holds at least one point per 2 x 2 mm
  // square of it (more where triangles share an edge or the grid is sheared).
  EXPECT_GT(points.size(), 0.0112 / (0.002 * 0.002));
  EXPECT_LT(points.size(), 4 * 0.0112 / (0.002 * 0.002));
}

// A long thin face (a box's wall, 30 x 6 cm, two triangles) is sampled about as densely as a
// square one, and a mesh of triangles smaller than the spacing gives one point per triangle:
// a wall next to the hand does not use up the points meant for the object it holds.
TEST(SurfaceSamples, LongThinAndTinyTrianglesAreSampledAtTheSpacing) {
  const Eigen::Vector3f half(0.15f, 0.0005f, 0.03f);
  const TriangleMesh wall = box_mesh(half);
  std::vector<Eigen::Vector3f> points;
  sample_mesh_near(wall, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(),
                   Eigen::Vector3d::Constant(0.2), 0.002, 1000000, points);
  const double area_m2 = 2 * (0.30 * 0.06 + 0.30 * 0.001 + 0.06 * 0.001);
  EXPECT_GT(points.size(), area_m2 / (0.002 * 0.002));
  EXPECT_LT(points.size(), 3 * area_m2 / (0.002 * 0.002));

  TriangleMesh tiny;  // 100 triangles 1 mm across, side by side
  for (int k = 0; k < 100; ++k) {
    const float x = 0.002f * float(k);
    tiny.vertices.push_back({x, 0.0f, 0.0f});
    tiny.vertices.push_back({x + 0.001f, 0.0f, 0.0f});
    tiny.vertices.push_back({x, 0.001f, 0.0f});
    tiny.triangles.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  points.clear();
  sample_mesh_near(tiny, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(),
                   Eigen::Vector3d::Constant(0.5), 0.0025, 1000000, points);
  EXPECT_EQ(points.size(), 100u);
}

TEST(SurfaceSamples, AMeshOutsideTheRegionGivesNothingAndTheCapHolds) {
  const TriangleMesh box = box_mesh(Eigen::Vector3f(0.05f, 0.05f, 0.05f));
  std::vector<Eigen::Vector3f> points;
  const Eigen::Isometry3d far(Eigen::Translation3d(0.5, 0.0, 0.0));
  sample_mesh_near(box, Eigen::Isometry3d::Identity(), far, Eigen::Vector3d::Constant(0.1), 0.002,
                   1000, points);
  EXPECT_TRUE(points.empty());
  sample_mesh_near(box, Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity(),
                   Eigen::Vector3d::Constant(0.1), 0.002, 1000, points);
  EXPECT_EQ(points.size(), 1000u);
}

}  // namespace
}  // namespace antipode::cells
