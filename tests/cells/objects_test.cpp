#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "mesh_objects.hpp"
#include "primitive_meshes.hpp"
#include "procedural_objects.hpp"

namespace antipode::cells {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(PrimitiveMeshes, EncloseTheirVolumes) {
  EXPECT_NEAR(box_mesh({0.01f, 0.02f, 0.03f}).volume(), 0.02 * 0.04 * 0.06, 1e-9);
  EXPECT_NEAR(cylinder_mesh(0.025f, 0.1f, 64).volume(), kPi * 0.025 * 0.025 * 0.1, 2e-6);
  EXPECT_NEAR(ellipsoid_mesh(Eigen::Vector3f::Constant(0.03f), 48).volume(),
              4.0 / 3.0 * kPi * 0.03 * 0.03 * 0.03, 3e-6);
  const double r = 0.02, h = 0.05;
  EXPECT_NEAR(capsule_mesh(float(r), float(h), 48).volume(),
              kPi * r * r * h + 4.0 / 3.0 * kPi * r * r * r, 3e-6);
  EXPECT_TRUE(cylinder_mesh(0.02f, 0.1f).volume_centroid().norm() < 1e-6);
}

TEST(ProceduralObjects, MostAreGraspableSomeAreNot) {
  RandomStream random(3);
  int graspable = 0;
  const int n = 200;
  for (int i = 0; i < n; ++i) {
    const auto& shapes = procedural_shapes();
    const ObjectModel m = make_random_object(shapes[i % shapes.size()], ProceduralRanges{}, random);
    const double density = m.mass_kg / m.visual->volume();
    EXPECT_GT(m.mass_kg, 0.0);
    if (m.mass_kg > 0.006) {
      EXPECT_GE(density, 399.0);
      EXPECT_LE(density, 1001.0);
    }
    EXPECT_LE(m.friction, 1.0);
    if (m.graspable_width_m >= 0.03 && m.graspable_width_m <= 0.07) ++graspable;
  }
  EXPECT_GT(graspable, n * 6 / 10);
  EXPECT_LT(graspable, n);
}

TEST(ProceduralObjects, SameSeedSameObject) {
  RandomStream a(11), b(11);
  const ObjectModel x = make_random_object("box", ProceduralRanges{}, a);
  const ObjectModel y = make_random_object("box", ProceduralRanges{}, b);
  EXPECT_EQ(x.mass_kg, y.mass_kg);
  EXPECT_EQ(x.collision.half_extents_m, y.collision.half_extents_m);
}

TEST(ProceduralObjects, RejectsUnknownShapesAndBadSizes) {
  EXPECT_THROW(make_object("torus", {0.05}, 500, 0.8), Error);
  EXPECT_THROW(make_object("box", {0.05, 0.05}, 500, 0.8), Error);
  EXPECT_THROW(make_object("cylinder", {-0.05, 0.1}, 500, 0.8), Error);
}

TEST(MeshObjects, LoadsYcbAndBlobsWhenTheDataIsThere) {
  const std::string data = ANTIPODE_TEST_DATA_DIR;
  if (!std::filesystem::exists(data + "/objects/ycb/025_mug/visual.obj"))
    GTEST_SKIP() << "shared data not found at " << data;
  const ObjectModel mug = load_mesh_object(data + "/objects/ycb", "025_mug", 1.0, 700, 0.8);
  EXPECT_GT(mug.collision.hulls.size(), 1u);
  EXPECT_GT(mug.visual->triangles.size(), 10000u);
  EXPECT_LT(mug.visual->bounds().center().norm(), 0.03f);
  const ObjectModel blob = load_mesh_object(data + "/objects/blobs", "007", 0.015, 700, 0.8);
  EXPECT_EQ(blob.collision.hulls.size(), 1u);
  EXPECT_GT(blob.visual->bounds().sizes().maxCoeff(), 0.01f);
  EXPECT_LT(blob.visual->bounds().sizes().maxCoeff(), 0.2f);
  EXPECT_EQ(list_mesh_objects(data + "/objects/ycb").size(), 15u);
}

}  // namespace
}  // namespace antipode::cells
