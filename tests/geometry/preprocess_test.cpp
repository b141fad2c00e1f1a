#include "antipode/geometry/preprocess.hpp"

#include <algorithm>
#include <limits>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

const float kNan = std::numeric_limits<float>::quiet_NaN();

Cloud two_view_cloud() {
  Cloud cloud;
  cloud.frame = "base";
  cloud.view_origins_m = {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(1, 0, 0)};
  // Two points in one 3 mm voxel (seen from different views), one alone in another.
  cloud.points_m = {{0.0005f, 0.0005f, 0.0005f}, {0.0025f, 0.0015f, 0.0005f}, {0.0105f, 0, 0}};
  cloud.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  cloud.view_masks = {1u, 2u, 1u};
  return cloud;
}

std::string error_of(const Cloud& cloud, const PreprocessOptions& options) {
  try {
    preprocess(cloud, options);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(PreprocessTest, RemoveNonFiniteKeepsArraysAligned) {
  Cloud cloud = two_view_cloud();
  cloud.points_m[1].y() = kNan;
  const Cloud out = remove_non_finite(cloud);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out.view_masks, (std::vector<std::uint32_t>{1u, 1u}));
  EXPECT_TRUE(out.normals[1].isApprox(Eigen::Vector3f(1, 0, 0)));
  EXPECT_EQ(out.view_origins_m.size(), 2u);
  EXPECT_EQ(out.frame, "base");
}

TEST(PreprocessTest, CropIsInclusive) {
  const Cloud cloud = two_view_cloud();
  AxisBox box;
  box.min_m = Eigen::Vector3f(0, 0, 0);
  box.max_m = Eigen::Vector3f(0.0105f, 0.01f, 0.01f);
  EXPECT_EQ(crop(cloud, box).size(), 3u);
  box.max_m.x() = 0.01f;
  EXPECT_EQ(crop(cloud, box).size(), 2u);
}

TEST(PreprocessTest, VoxelsAverageAndOrTheirViewMasks) {
  const Cloud out = voxelize(two_view_cloud(), 0.003f);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out.points_m[0].isApprox(Eigen::Vector3f(0.0015f, 0.001f, 0.0005f)));
  EXPECT_EQ(out.view_masks[0], 3u);
  EXPECT_EQ(out.view_masks[1], 1u);
  EXPECT_TRUE(out.normals[0].isApprox(Eigen::Vector3f(0, 1, 1).normalized()));
  EXPECT_NO_THROW(out.validate());
}

TEST(PreprocessTest, VoxelOutputDoesNotDependOnInputOrder) {
  Cloud cloud;
  for (int i = 0; i < 500; ++i) {
    cloud.points_m.emplace_back(0.0007f * (i % 37), 0.0011f * (i % 23), 0.0013f * (i % 11));
  }
  Cloud reversed = cloud;
  std::reverse(reversed.points_m.begin(), reversed.points_m.end());
  const Cloud a = voxelize(cloud, 0.003f);
  const Cloud b = voxelize(reversed, 0.003f);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a.points_m[i].isApprox(b.points_m[i]));
  EXPECT_TRUE(a.view_masks.empty());
}

TEST(PreprocessTest, VoxelSizeMustBePositive) {
  EXPECT_THROW(voxelize(two_view_cloud(), 0.0f), Error);
  EXPECT_THROW(voxelize(two_view_cloud(), -1.0f), Error);
  Cloud far = two_view_cloud();
  far.points_m[0].x() = 1e5f;
  EXPECT_THROW(voxelize(far, 0.003f), Error);
}

TEST(PreprocessTest, PreprocessRunsEveryStep) {
  Cloud cloud = two_view_cloud();
  cloud.points_m.emplace_back(kNan, 0, 0);
  cloud.normals.emplace_back(0, 0, 1);
  cloud.view_masks.push_back(1u);
  PreprocessOptions options;
  options.workspace = AxisBox{Eigen::Vector3f(-1, -1, -1), Eigen::Vector3f(0.005f, 1, 1)};
  const Cloud out = preprocess(cloud, options);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out.view_masks[0], 3u);
  options.voxel_size_m = 0.0f;
  EXPECT_EQ(preprocess(cloud, options).size(), 2u);
}

TEST(PreprocessTest, UnusableInputIsAClearError) {
  PreprocessOptions options;
  EXPECT_EQ(error_of(Cloud{}, options), "the cloud has no points");
  Cloud nans;
  nans.points_m.assign(3, Eigen::Vector3f(kNan, 0, 0));
  EXPECT_EQ(error_of(nans, options), "the cloud has no finite point (all 3 are NaN or infinite)");
  options.workspace = AxisBox{Eigen::Vector3f(2, 2, 2), Eigen::Vector3f(3, 3, 3)};
  EXPECT_EQ(error_of(two_view_cloud(), options),
            "no point of the cloud lies in the workspace [2, 2, 2] .. [3, 3, 3] (the cloud spans "
            "[0.0005, 0, 0] .. [0.0105, 0.0015, 0.0005] in frame 'base')");
  options.workspace = AxisBox{Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(-1, 1, 1)};
  EXPECT_EQ(error_of(two_view_cloud(), options),
            "workspace: min x (0.000000) is above max x "
            "(-1.000000)");
}

}  // namespace
}  // namespace antipode
