// The support plane: found under objects standing on a table, not on objects alone.
#include "antipode/geometry/support_plane.hpp"

#include <filesystem>
#include <iostream>

#include <gtest/gtest.h>

#include "antipode/geometry/preprocess.hpp"
#include "antipode/io/load_cloud.hpp"
#include "synthetic_shapes.hpp"

namespace antipode {
namespace {

const Eigen::Vector3f kSensor = Eigen::Vector3f::Zero();

// A table seen from above at 45 degrees with a can standing on it.
struct TableScene {
  Eigen::Vector3d up = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();
  Eigen::Vector3d on_table{0.0, 0.0, 0.7};
  Cloud cloud;
  TableScene() {
    cloud = testing::plane_cloud(on_table, up, 0.5);
    testing::append(cloud, testing::cylinder_cloud(on_table + 0.06 * up, up, 0.05, 0.12));
    cloud = preprocess(cloud, PreprocessOptions{});
  }
};

TEST(SupportPlaneTest, FindsTheTableUnderACan) {
  const TableScene scene;
  const auto plane = find_support_plane(scene.cloud, kSensor, SupportPlaneOptions{}, RandomStream(3));
  ASSERT_TRUE(plane.has_value());
  EXPECT_GT(plane->normal.cast<double>().dot(scene.up), 0.999);
  EXPECT_NEAR(plane->distance(scene.on_table.cast<float>()), 0.0f, 0.002f);
  EXPECT_GT(plane->distance(kSensor), 0.0f);
  EXPECT_GT(plane->inliers, scene.cloud.size() / 2);
}

TEST(SupportPlaneTest, IsDeterministic) {
  const TableScene scene;
  const auto a = find_support_plane(scene.cloud, kSensor, SupportPlaneOptions{}, RandomStream(5));
  const auto b = find_support_plane(scene.cloud, kSensor, SupportPlaneOptions{}, RandomStream(5));
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->normal, b->normal);
  EXPECT_EQ(a->offset, b->offset);
  EXPECT_EQ(a->inliers, b->inliers);
}

TEST(SupportPlaneTest, NoSupportUnderObjectsAlone) {
  const Eigen::Vector3d centre(0.02, -0.01, 0.6);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, 1.0, 0.1).normalized();
  const Cloud cylinder =
      preprocess(testing::cylinder_cloud(centre, axis, 0.066, 0.2), PreprocessOptions{});
  EXPECT_FALSE(find_support_plane(cylinder, kSensor, SupportPlaneOptions{}, RandomStream(1)));
  const Cloud box = preprocess(
      testing::box_cloud(centre, Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.05, 0.08, 0.12)),
      PreprocessOptions{});
  EXPECT_FALSE(find_support_plane(box, kSensor, SupportPlaneOptions{}, RandomStream(1)));
  const Cloud sphere = preprocess(testing::sphere_cloud(centre, 0.07), PreprocessOptions{});
  EXPECT_FALSE(find_support_plane(sphere, kSensor, SupportPlaneOptions{}, RandomStream(1)));
}

std::string shared_cloud(const std::string& name) {
  return std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/" + name;
}

TEST(SupportPlaneTest, TableOfTableMug) {
  const std::string path = shared_cloud("table_mug.pcd");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  const auto plane = find_support_plane(cloud, kSensor, SupportPlaneOptions{}, RandomStream(1));
  ASSERT_TRUE(plane.has_value());
  // The table is seen from above and in front: its normal points up (-y in the sensor
  // frame) and towards the sensor (-z).
  EXPECT_LT(plane->normal.y(), -0.5f);
  EXPECT_LT(plane->normal.z(), -0.3f);
  EXPECT_GT(plane->inliers, cloud.size() / 2);
  std::size_t mug = 0;
  for (const auto& p : cloud.points_m) mug += plane->distance(p) > 0.02f;
  std::cout << "table_mug: normal " << plane->normal.transpose() << " offset " << plane->offset
            << " inliers " << plane->inliers << " of " << cloud.size() << ", " << mug
            << " points more than 2 cm above\n";
  EXPECT_GT(mug, 1000u);
}

TEST(SupportPlaneTest, NoSupportUnderTheKrylonCan) {
  const std::string path = shared_cloud("krylon.pcd");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  EXPECT_FALSE(find_support_plane(cloud, kSensor, SupportPlaneOptions{}, RandomStream(1)));
  EXPECT_FALSE(find_support_plane(cloud, Eigen::Vector3f(0, 0, -1), SupportPlaneOptions{},
                                  RandomStream(1)));
}

}  // namespace
}  // namespace antipode
