// Scene understanding on synthetic single-view clouds (a sensor at the origin): the support
// is the plane objects stand on, not the largest one, and the objects are its segments.
#include "antipode/geometry/scene_layout.hpp"

#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "synthetic_shapes.hpp"

namespace antipode {
namespace {

using testing::ShapeOptions;

const Eigen::Vector3d kUp = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();  // seen at 45 deg
const Eigen::Vector3d kOnTable(0.0, 0.0, 0.8);
const Eigen::Vector3d kAcross = Eigen::Vector3d::UnitX();       // along the table
const Eigen::Vector3d kAway = kUp.cross(kAcross).normalized();  // table depth, from sensor

ShapeOptions sparse() {
  ShapeOptions o;
  o.spacing_m = 0.004;
  return o;
}

Cloud prepared(const Cloud& raw) { return preprocess(raw, PreprocessOptions{}); }

// Two cans standing on a table, the floor 0.7 m below it (wider than the table) and a wall
// behind, each plane holding more points than the table top.
Cloud room() {
  Cloud cloud = testing::plane_cloud(kOnTable, kUp, 0.4, sparse());
  testing::append(cloud,
                  testing::plane_cloud(kOnTable - 0.7 * kUp + 0.3 * kAway, kUp, 1.2, sparse()));
  testing::append(cloud,
                  testing::plane_cloud(kOnTable + 0.6 * kAway + 0.3 * kUp, -kAway, 1.0, sparse()));
  for (const double x : {-0.08, 0.07}) {
    testing::append(cloud,
                    testing::cylinder_cloud(kOnTable + x * kAcross + 0.05 * kUp, kUp, 0.05, 0.1));
  }
  return cloud;
}

double height_above_table(const Eigen::Vector3f& p) {
  return (p.cast<double>() - kOnTable).dot(kUp);
}

TEST(SceneLayoutTest, TheSupportIsThePlaneObjectsStandOnNotTheLargest) {
  const Cloud cloud = prepared(room());
  const SceneLayout layout =
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(3));
  ASSERT_TRUE(layout.support.has_value()) << layout.summary();
  EXPECT_GT(layout.support->normal.cast<double>().dot(kUp), 0.999);
  EXPECT_NEAR(layout.support->distance(kOnTable.cast<float>()), 0.0, 0.003);
  EXPECT_GE(layout.planes, 3u);
  ASSERT_EQ(layout.objects.size(), 2u) << layout.summary();
  for (const SceneObject& object : layout.objects) {
    EXPECT_GT(object.points.size(), 100u);
    EXPECT_NEAR(object.height_m, 0.1, 0.01);
    for (const std::int32_t i : object.points) {
      EXPECT_GT(height_above_table(cloud.points_m[std::size_t(i)]), 0.005);
      EXPECT_EQ(layout.object_of_point[std::size_t(i)], object.id);
    }
  }
  EXPECT_LT(layout.objects[0].centroid_m.x(), 0.0f);
  EXPECT_GT(layout.objects[1].centroid_m.x(), 0.0f);
  EXPECT_NE(layout.summary().find("2 objects"), std::string::npos) << layout.summary();
}

TEST(SceneLayoutTest, ObjectsAFewMillimetresApartAreSeparateSegments) {
  Cloud raw = testing::plane_cloud(kOnTable, kUp, 0.4, sparse());
  Eigen::Matrix3d rotation;
  rotation << kAcross, kAway, kUp;
  const double gap = 0.008;
  for (const double side : {-1.0, 1.0}) {
    const Eigen::Vector3d centre = kOnTable + side * (0.02 + gap / 2) * kAcross + 0.03 * kUp;
    testing::append(raw, testing::box_cloud(centre, rotation, {0.04, 0.05, 0.06}));
  }
  const SceneLayout layout =
      find_scene_layout(prepared(raw), Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(1));
  EXPECT_EQ(layout.objects.size(), 2u) << layout.summary();
}

// --explain's sizes: along the support, whatever the cloud's axes - a 5 x 4 cm box, 6 cm
// tall, turned on a table seen at 45 degrees.
TEST(SceneLayoutTest, ObjectsAreSizedAlongTheSupport) {
  Cloud raw = testing::plane_cloud(kOnTable, kUp, 0.4, sparse());
  Eigen::Matrix3d rotation;
  rotation << kAcross, kAway, kUp;
  rotation = Eigen::AngleAxisd(0.5, kUp) * rotation;
  testing::append(raw, testing::box_cloud(kOnTable + 0.03 * kUp, rotation, {0.05, 0.04, 0.06}));
  const Cloud cloud = prepared(raw);
  const SceneLayout layout =
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(1));
  ASSERT_EQ(layout.objects.size(), 1u) << layout.summary();
  const std::string text = describe_scene(layout.support, layout.objects, cloud.points_m);
  double a = 0.0, b = 0.0, h = 0.0;
  const auto at = text.find("#0: ");
  ASSERT_NE(at, std::string::npos) << text;
  ASSERT_EQ(std::sscanf(text.c_str() + at,
                        "#0: %*d points, %lf x %lf cm on the support, %lf cm tall", &a, &b, &h),
            3)
      << text;
  EXPECT_NEAR(a, 5.0, 0.5) << text;
  EXPECT_NEAR(b, 4.0, 0.5) << text;
  EXPECT_NEAR(h, 6.0, 0.5) << text;
}

TEST(SceneLayoutTest, WithoutASupportTheWholeCloudIsLeftAlone) {
  const Cloud cloud = prepared(testing::sphere_cloud(kOnTable, 0.06));
  const SceneLayout layout =
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(1));
  EXPECT_FALSE(layout.support.has_value());
  EXPECT_TRUE(layout.objects.empty());
  EXPECT_EQ(layout.object_of_point, std::vector<std::int32_t>(cloud.size(), -1));
  EXPECT_EQ(layout.summary(), "no support surface: the whole cloud is used");
}

TEST(SceneLayoutTest, ATiltedTableIsStillTheSupport) {
  const Eigen::Vector3d up =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()) * Eigen::Vector3d(0.0, -1.0, 0.0);
  Cloud raw = testing::plane_cloud(kOnTable, up, 0.4, sparse());
  testing::append(raw, testing::cylinder_cloud(kOnTable + 0.05 * up, up, 0.05, 0.1));
  const SceneLayout layout =
      find_scene_layout(prepared(raw), Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(1));
  ASSERT_TRUE(layout.support.has_value());
  EXPECT_GT(layout.support->normal.cast<double>().dot(up), 0.999);
  EXPECT_EQ(layout.objects.size(), 1u);
  // Told that up is -y, the same table (tilted about 29 degrees from level) is no support
  // within 20 degrees.
  SceneOptions level;
  level.up = Eigen::Vector3f(0.0f, -1.0f, 0.0f);
  level.max_tilt_deg = 20.0f;
  EXPECT_FALSE(find_scene_layout(prepared(raw), Eigen::Vector3f::Zero(), level, RandomStream(1))
                   .support.has_value());
}

TEST(SceneLayoutTest, FixturesAreNotObjectsAndTheResultDependsOnTheSeedOnly) {
  const Cloud cloud = prepared(room());
  SceneOptions options;
  const Eigen::Vector3f left = (kOnTable - 0.08 * kAcross + 0.05 * kUp).cast<float>();
  options.fixtures.push_back(
      {left - Eigen::Vector3f::Constant(0.06f), left + Eigen::Vector3f::Constant(0.06f)});
  const SceneLayout a = find_scene_layout(cloud, Eigen::Vector3f::Zero(), options, RandomStream(5));
  const SceneLayout b = find_scene_layout(cloud, Eigen::Vector3f::Zero(), options, RandomStream(5));
  ASSERT_EQ(a.objects.size(), 1u) << a.summary();
  EXPECT_GT(a.objects[0].centroid_m.x(), 0.0f);
  EXPECT_EQ(a.object_of_point, b.object_of_point);
}

// A stretch of the table 1.2 cm above the rest (as the far end of a real table, bent by the
// sensor's depth error, can be) is no object; a marker pen lying down, 1.9 cm high, is.
TEST(SceneLayoutTest, AnObjectRisesAtLeastTheLeastHeightAboveTheSupport) {
  Cloud raw = testing::plane_cloud(kOnTable, kUp, 0.4, sparse());
  testing::append(raw,
                  testing::plane_cloud(kOnTable + 0.012 * kUp + 0.12 * kAway, kUp, 0.08, sparse()));
  testing::append(
      raw, testing::cylinder_cloud(kOnTable - 0.1 * kAway + 0.0095 * kUp, kAcross, 0.019, 0.13));
  testing::append(raw,
                  testing::cylinder_cloud(kOnTable + 0.08 * kAcross + 0.05 * kUp, kUp, 0.05, 0.1));
  const Cloud cloud = prepared(raw);
  const SceneLayout layout =
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(2));
  ASSERT_EQ(layout.objects.size(), 2u) << layout.summary();
  for (const SceneObject& object : layout.objects) {
    EXPECT_LT((object.centroid_m.cast<double>() - kOnTable).dot(kAway), 0.06) << layout.summary();
    EXPECT_GE(object.height_m, SceneOptions{}.min_object_height_m);
  }
  SceneOptions lenient;  // down to the inlier distance: the raised stretch is an object too
  lenient.min_object_height_m = lenient.plane_distance_m;
  EXPECT_EQ(
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), lenient, RandomStream(2)).objects.size(),
      3u);
}

// A pile's upper layer hides its own lower part: a box lying 1 cm above another (the gap
// between them hidden in a real pile) rests on it and is an object; a box as high above
// the table with nothing under it is not.
TEST(SceneLayoutTest, AnObjectRestingOnAnotherIsAnObjectAFloatingOneIsNot) {
  Cloud raw = testing::plane_cloud(kOnTable, kUp, 0.4, sparse());
  Eigen::Matrix3d rotation;
  rotation << kAcross, kAway, kUp;
  const Eigen::Vector3d standing = kOnTable - 0.06 * kAcross + 0.03 * kUp;  // 6 cm tall
  testing::append(raw, testing::box_cloud(standing, rotation, {0.05, 0.05, 0.06}));
  testing::append(raw, testing::box_cloud(standing + 0.055 * kUp, rotation, {0.08, 0.04, 0.03}));
  const Eigen::Vector3d floating = kOnTable + 0.1 * kAcross + 0.085 * kUp;
  testing::append(raw, testing::box_cloud(floating, rotation, {0.05, 0.04, 0.03}));
  const Cloud cloud = prepared(raw);
  const SceneLayout layout =
      find_scene_layout(cloud, Eigen::Vector3f::Zero(), SceneOptions{}, RandomStream(1));
  ASSERT_EQ(layout.objects.size(), 2u) << layout.summary();
  for (const SceneObject& object : layout.objects)
    EXPECT_LT(object.centroid_m.cast<double>().dot(kAcross), 0.0) << layout.summary();
  const auto [lower, higher] = std::minmax(layout.objects[0].height_m, layout.objects[1].height_m);
  EXPECT_NEAR(lower, 0.06, 0.005) << layout.summary();   // the standing box's top
  EXPECT_NEAR(higher, 0.10, 0.005) << layout.summary();  // the resting box's
  SceneOptions standing_only;
  standing_only.max_rest_gap_m = 0.0f;
  EXPECT_EQ(find_scene_layout(cloud, Eigen::Vector3f::Zero(), standing_only, RandomStream(1))
                .objects.size(),
            1u);
}

TEST(SceneLayoutTest, InvalidOptionsAreErrors) {
  SceneOptions options;
  options.cluster_tolerance_m = 0.0f;
  EXPECT_THROW(
      find_scene_layout(prepared(room()), Eigen::Vector3f::Zero(), options, RandomStream(1)),
      Error);
  options = SceneOptions{};
  options.up = Eigen::Vector3f(0.0f, 0.0f, 2.0f);
  try {
    options.validate();
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "scene: up must be a unit vector");
  }
  options = SceneOptions{};
  options.min_object_height_m = 0.005f;  // below the inlier distance
  EXPECT_THROW(options.validate(), Error);
  options = SceneOptions{};
  options.max_rest_gap_m = -0.01f;
  EXPECT_THROW(options.validate(), Error);
}

}  // namespace
}  // namespace antipode
