#include "antipode/io/save_cloud.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include "antipode/core/error.hpp"
#include "antipode/io/load_cloud.hpp"
#include "temp_dir.hpp"

namespace antipode {
namespace {

using testing::TempDir;

Cloud two_view_cloud() {
  Cloud cloud;
  cloud.frame = "base";
  cloud.view_origins_m = {Eigen::Vector3f(0.3f, 0.4f, 0.25f), Eigen::Vector3f(0.3f, -0.8f, 0.25f)};
  for (int i = 0; i < 300; ++i) {
    cloud.points_m.emplace_back(0.5f + 0.001f * i, -0.2f + 0.0003f * (i % 11), -0.29f + 1e-4f * i);
    cloud.view_masks.push_back(1u + std::uint32_t(i % 3));  // 1, 2 and 3: seen by both
  }
  return cloud;
}

TEST(SaveCloudTest, LoadCloudReadsBackEveryPointExactly) {
  const TempDir dir;
  const Cloud cloud = two_view_cloud();
  save_cloud_pcd(cloud, dir.file("cycle.pcd"));
  const Cloud loaded = load_cloud(dir.file("cycle.pcd"));
  ASSERT_EQ(loaded.size(), cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    EXPECT_EQ(loaded.points_m[i], cloud.points_m[i]) << i;
  // The view masks come back beside them (load_cloud itself gives a file one view).
  EXPECT_EQ(load_view_masks(dir.file("cycle.pcd")), cloud.view_masks);
}

TEST(SaveCloudTest, PclReadsThePointsAndTheViewThatSawEach) {
  const TempDir dir;
  const Cloud cloud = two_view_cloud();
  save_cloud_pcd(cloud, dir.file("cycle.pcd"));
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPCDFile(dir.file("cycle.pcd"), blob), 0);
  EXPECT_EQ(blob.width * blob.height, cloud.size());
  ASSERT_EQ(blob.fields.size(), 4u);
  EXPECT_EQ(blob.fields[3].name, "view");
  EXPECT_EQ(blob.fields[3].datatype, pcl::PCLPointField::UINT32);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::uint32_t view = 0;
    std::memcpy(&view, &blob.data[i * blob.point_step + blob.fields[3].offset], 4);
    EXPECT_EQ(view, cloud.view_masks[i]) << i;
  }
}

TEST(SaveCloudTest, ACloudWithoutViewMasksHasOnlyItsCoordinates) {
  const TempDir dir;
  Cloud cloud = two_view_cloud();
  cloud.view_masks.clear();
  save_cloud_pcd(cloud, dir.file("plain.pcd"));
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPCDFile(dir.file("plain.pcd"), blob), 0);
  EXPECT_EQ(blob.fields.size(), 3u);
  EXPECT_EQ(load_cloud(dir.file("plain.pcd")).size(), cloud.size());
  EXPECT_TRUE(load_view_masks(dir.file("plain.pcd")).empty());
}

// Masks stay with their points where load_cloud drops non-finite ones, also in the
// compressed encoding PCL writes.
TEST(SaveCloudTest, ViewMasksFollowTheFinitePointsOfACompressedFile) {
  const TempDir dir;
  pcl::PointCloud<pcl::PointXYZL> cloud;  // the label stands for the `view` field: U, 4 bytes
  for (std::uint32_t i = 0; i < 50; ++i) {
    pcl::PointXYZL p;
    p.x = 0.01f * float(i), p.y = i % 7 == 3 ? std::nanf("") : 0.2f, p.z = 0.5f, p.label = i;
    cloud.push_back(p);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2(cloud, blob);
  for (auto& field : blob.fields)
    if (field.name == "label") field.name = "view";
  pcl::PCDWriter writer;
  ASSERT_EQ(writer.writeBinaryCompressed(dir.file("labels.pcd"), blob), 0);
  std::vector<std::uint32_t> expected;
  for (std::uint32_t i = 0; i < 50; ++i)
    if (i % 7 != 3) expected.push_back(i);
  EXPECT_EQ(load_cloud(dir.file("labels.pcd")).size(), expected.size());
  EXPECT_EQ(load_view_masks(dir.file("labels.pcd")), expected);
}

TEST(SaveCloudTest, AFolderThatIsMissingIsAnErrorNamingThePathAndLeavesNothing) {
  const TempDir dir;
  const std::string path = dir.file("missing/cycle.pcd");
  try {
    save_cloud_pcd(two_view_cloud(), path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace antipode
