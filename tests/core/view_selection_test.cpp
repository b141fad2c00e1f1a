// Selecting the points some views of a cloud saw.
#include <gtest/gtest.h>

#include "antipode/core/view_selection.hpp"
#include "support/error_of.hpp"

namespace antipode {
namespace {

using testing::error_of;

// Point 0 seen by view 0, point 1 by view 1, point 2 by both, point 3 by view 2.
Cloud three_views() {
  Cloud cloud;
  for (int i = 0; i < 4; ++i) cloud.points_m.emplace_back(static_cast<float>(i), 0.0f, 0.0f);
  cloud.view_masks = {1u, 2u, 3u, 4u};
  cloud.view_origins_m = {{0, 0, 1}, {0, 0, 2}, {0, 0, 3}};
  return cloud;
}

TEST(ViewSelectionTest, KeepsThePointsOfTheViewsRenumberingThem) {
  std::vector<std::int32_t> new_index;
  const Cloud right = points_of_views(three_views(), {1}, &new_index);
  ASSERT_EQ(right.size(), 2u);
  EXPECT_EQ(right.points_m[0].x(), 1.0f);
  EXPECT_EQ(right.points_m[1].x(), 2.0f);
  EXPECT_EQ(right.view_masks, (std::vector<std::uint32_t>{1u, 1u}));
  ASSERT_EQ(right.view_origins_m.size(), 1u);
  EXPECT_EQ(right.view_origins_m[0].z(), 2.0f);
  EXPECT_EQ(new_index, (std::vector<std::int32_t>{-1, 0, 1, -1}));
  EXPECT_NO_THROW(right.validate());
}

TEST(ViewSelectionTest, KeepsNormalsAndFrame) {
  Cloud cloud = three_views();
  cloud.frame = "sensor";
  for (int i = 0; i < 4; ++i) cloud.normals.push_back(Eigen::Vector3f::Unit(i % 3));
  const Cloud left = points_of_views(cloud, {0});
  EXPECT_EQ(left.frame, "sensor");
  ASSERT_EQ(left.normals.size(), 2u);  // points 0 and 2
  EXPECT_EQ(left.normals[1], Eigen::Vector3f::UnitZ());
  EXPECT_NO_THROW(left.validate());
}

TEST(ViewSelectionTest, ViewsAreNumberedInTheOrderListed) {
  const Cloud two = points_of_views(three_views(), {2, 0});
  ASSERT_EQ(two.size(), 3u);  // points 0, 2 and 3
  EXPECT_EQ(two.view_masks, (std::vector<std::uint32_t>{2u, 2u, 1u}));
  EXPECT_EQ(two.view_origins_m[0].z(), 3.0f);
  EXPECT_EQ(two.view_origins_m[1].z(), 1.0f);
}

TEST(ViewSelectionTest, RefusesNoViewsAndViewsTheCloudLacks) {
  EXPECT_EQ(error_of([] { points_of_views(three_views(), {}); }), "view selection: no view given");
  EXPECT_EQ(error_of([] { points_of_views(three_views(), {3}); }),
            "view selection: view 3 is not in the cloud, which has 3 view(s)");
  EXPECT_EQ(error_of([] {
              points_of_views(three_views(), {1, 0, 1});
            }),
            "view selection: view 1 is listed twice");
  Cloud no_views = three_views();
  no_views.view_masks.clear();
  no_views.view_origins_m.clear();
  const Cloud all = points_of_views(no_views, {0});  // one view: view 0
  EXPECT_EQ(all.size(), 4u);
  EXPECT_TRUE(all.view_masks.empty());
  EXPECT_NO_THROW(all.validate());
  EXPECT_NE(error_of([&] { points_of_views(no_views, {1}); }).find("which has 1 view(s)"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode
