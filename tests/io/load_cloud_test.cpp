#include "antipode/io/load_cloud.hpp"

#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include "temp_dir.hpp"

namespace antipode {
namespace {

using testing::TempDir;

pcl::PointCloud<pcl::PointXYZ> small_cloud() {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 200; ++i) {
    cloud.push_back(pcl::PointXYZ(0.001f * i, 0.01f * (i % 7) - 0.03f, 0.9f + 0.0007f * (i % 13)));
  }
  cloud.sensor_origin_ = Eigen::Vector4f(0.1f, -0.2f, 0.3f, 0.0f);
  return cloud;
}

void expect_same_points(const Cloud& loaded, const pcl::PointCloud<pcl::PointXYZ>& written,
                        float tolerance) {
  ASSERT_EQ(loaded.size(), written.size());
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    EXPECT_NEAR(loaded.points_m[i].x(), written[i].x, tolerance) << i;
    EXPECT_NEAR(loaded.points_m[i].y(), written[i].y, tolerance) << i;
    EXPECT_NEAR(loaded.points_m[i].z(), written[i].z, tolerance) << i;
  }
}

void expect_single_view(const Cloud& cloud, const Eigen::Vector3f& origin) {
  ASSERT_EQ(cloud.view_origins_m.size(), 1u);
  EXPECT_TRUE(cloud.view_origins_m[0].isApprox(origin, 1e-6f)) << cloud.view_origins_m[0];
  ASSERT_EQ(cloud.view_masks.size(), cloud.size());
  for (const auto mask : cloud.view_masks) EXPECT_EQ(mask, 1u);
  EXPECT_FALSE(cloud.has_normals());
  EXPECT_NO_THROW(cloud.validate());
}

TEST(LoadCloudTest, PcdRoundTripsInAllThreeEncodings) {
  TempDir dir;
  const auto written = small_cloud();
  pcl::io::savePCDFileASCII(dir.file("a.pcd"), written);
  pcl::io::savePCDFileBinary(dir.file("b.pcd"), written);
  pcl::io::savePCDFileBinaryCompressed(dir.file("c.pcd"), written);
  const Eigen::Vector3f origin(0.1f, -0.2f, 0.3f);
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd"}) {
    SCOPED_TRACE(name);
    const Cloud cloud = load_cloud(dir.file(name));
    expect_same_points(cloud, written, name[0] == 'a' ? 1e-6f : 0.0f);
    expect_single_view(cloud, origin);
    EXPECT_EQ(cloud.frame, "sensor");
  }
}

TEST(LoadCloudTest, OptionsOverrideOriginAndFrame) {
  TempDir dir;
  pcl::io::savePCDFileBinary(dir.file("b.pcd"), small_cloud());
  LoadCloudOptions options;
  options.view_origin_m = Eigen::Vector3f(1.0f, 2.0f, 3.0f);
  options.frame = "camera_left";
  const Cloud cloud = load_cloud(dir.file("b.pcd"), options);
  expect_single_view(cloud, Eigen::Vector3f(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(cloud.frame, "camera_left");
}

TEST(LoadCloudTest, OrganisedCloudLosesItsHolesAndKeepsOrder) {
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZ> organised(8, 5);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> finite;
  for (int row = 0; row < 5; ++row) {
    for (int col = 0; col < 8; ++col) {
      const bool hole = (row * 8 + col) % 3 == 0;
      const pcl::PointXYZ p(0.01f * col, 0.01f * row, 1.0f);
      organised(col, row) = hole ? pcl::PointXYZ(nan, nan, nan) : p;
      if (!hole) finite.push_back(p);
    }
  }
  organised.is_dense = false;
  pcl::io::savePCDFileBinary(dir.file("o.pcd"), organised);
  pcl::io::savePCDFileASCII(dir.file("o_ascii.pcd"), organised);
  expect_same_points(load_cloud(dir.file("o.pcd")), finite, 0.0f);
  expect_same_points(load_cloud(dir.file("o_ascii.pcd")), finite, 1e-6f);
}

TEST(LoadCloudTest, ExtraFieldsAreIgnored) {
  TempDir dir;
  pcl::PointCloud<pcl::PointXYZRGBNormal> rich;
  pcl::PointCloud<pcl::PointXYZ> plain;
  for (int i = 0; i < 50; ++i) {
    pcl::PointXYZRGBNormal p;
    p.x = 0.002f * i;
    p.y = -0.001f * i;
    p.z = 0.5f;
    p.r = 10;
    p.normal_x = 1.0f;
    p.curvature = 0.5f;
    rich.push_back(p);
    plain.push_back(pcl::PointXYZ(p.x, p.y, p.z));
  }
  pcl::io::savePCDFileASCII(dir.file("rich_a.pcd"), rich);
  pcl::io::savePCDFileBinaryCompressed(dir.file("rich_c.pcd"), rich);
  expect_same_points(load_cloud(dir.file("rich_a.pcd")), plain, 1e-6f);
  expect_same_points(load_cloud(dir.file("rich_c.pcd")), plain, 0.0f);
}

TEST(LoadCloudTest, DoublePrecisionAsciiFieldsAndCrlfLineEnds) {
  TempDir dir;
  testing::write_bytes(dir.file("d.pcd"),
                       "# .PCD v0.7\r\nVERSION 0.7\r\nFIELDS x y z intensity\r\nSIZE 8 8 8 4\r\n"
                       "TYPE F F F U\r\nCOUNT 1 1 1 1\r\nWIDTH 2\r\nHEIGHT 1\r\n"
                       "VIEWPOINT 0 0 0.5 1 0 0 0\r\nPOINTS 2\r\nDATA ascii\r\n"
                       "0.25 -1e-3 +2 7\r\n\r\nnan 0 0 1\r\n");
  const Cloud cloud = load_cloud(dir.file("d.pcd"));
  ASSERT_EQ(cloud.size(), 1u);
  EXPECT_TRUE(cloud.points_m[0].isApprox(Eigen::Vector3f(0.25f, -0.001f, 2.0f)));
  expect_single_view(cloud, Eigen::Vector3f(0.0f, 0.0f, 0.5f));
}

TEST(LoadCloudTest, PlyRoundTripsAsciiAndBinary) {
  TempDir dir;
  const auto written = small_cloud();
  pcl::io::savePLYFileASCII(dir.file("a.ply"), written);
  pcl::io::savePLYFileBinary(dir.file("b.ply"), written);
  for (const char* name : {"a.ply", "b.ply"}) {
    SCOPED_TRACE(name);
    const Cloud cloud = load_cloud(dir.file(name));
    expect_same_points(cloud, written, 1e-6f);
    expect_single_view(cloud, Eigen::Vector3f::Zero());
  }
}

TEST(LoadCloudTest, ExtensionIsCaseInsensitive) {
  TempDir dir;
  pcl::io::savePCDFileBinary(dir.file("UPPER.PCD"), small_cloud());
  EXPECT_EQ(load_cloud(dir.file("UPPER.PCD")).size(), 200u);
}

std::string shared_cloud(const std::string& name) {
  return std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/" + name;
}

TEST(LoadCloudTest, SharedCloudsLoadCompletely) {
  if (!std::filesystem::exists(shared_cloud("table_mug.pcd"))) {
    GTEST_SKIP() << "shared data not found at " << ANTIPODE_TEST_DATA_DIR;
  }
  const Cloud mug = load_cloud(shared_cloud("table_mug.pcd"));
  EXPECT_EQ(mug.size(), 104444u);
  expect_single_view(mug, Eigen::Vector3f::Zero());
  const Cloud krylon = load_cloud(shared_cloud("krylon.pcd"));
  EXPECT_EQ(krylon.size(), 4467u);
}

// A cloud moved into a robot's frame: every point and the view origin by the same pose; a
// VIEWPOINT rotation is reported, not applied.
TEST(LoadCloudTest, IntoAFrameMovesPointsAndOriginByThePose) {
  TempDir dir;
  auto written = small_cloud();
  written.sensor_orientation_ = Eigen::Quaternionf(0.0f, 1.0f, 0.0f, 0.0f);
  pcl::io::savePCDFileBinary(dir.file("c.pcd"), written);
  const Cloud in_file = load_cloud(dir.file("c.pcd"));
  const Eigen::Isometry3d X_BaseFile =
      Eigen::Translation3d(0.3, -0.6, 0.9) *
      Eigen::AngleAxisd(2.1, Eigen::Vector3d(1.0, -2.0, 0.5).normalized());
  LoadCloudOptions options;
  options.frame = "base";
  std::string note;
  const Cloud in_base = load_cloud_into(dir.file("c.pcd"), X_BaseFile, options, &note);
  EXPECT_EQ(in_base.frame, "base");
  ASSERT_EQ(in_base.size(), in_file.size());
  for (std::size_t i = 0; i < in_file.size(); ++i) {
    EXPECT_LT((in_base.points_m[i] - X_BaseFile.cast<float>() * in_file.points_m[i]).norm(), 1e-5f);
  }
  EXPECT_LT(
      (in_base.view_origins_m[0] - X_BaseFile.cast<float>() * in_file.view_origins_m[0]).norm(),
      1e-5f);
  EXPECT_NE(note.find("VIEWPOINT rotation (qw qx qy qz 0.000000 1.000000 0.000000 0.000000) is "
                      "not applied"),
            std::string::npos)
      << note;
  written.sensor_orientation_ = Eigen::Quaternionf::Identity();
  pcl::io::savePCDFileBinary(dir.file("d.pcd"), written);
  load_cloud_into(dir.file("d.pcd"), X_BaseFile, options, &note);
  EXPECT_EQ(note, "");
}

}  // namespace
}  // namespace antipode
