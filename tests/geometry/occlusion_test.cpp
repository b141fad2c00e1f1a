#include "antipode/geometry/occlusion.hpp"

#include <gtest/gtest.h>

namespace antipode {
namespace {

// A 20 cm square wall at z = 0.5, seen from the origin.
Cloud wall() {
  Cloud cloud;
  cloud.view_origins_m.push_back(Eigen::Vector3f::Zero());
  for (int i = -33; i <= 33; ++i) {
    for (int j = -33; j <= 33; ++j) {
      cloud.points_m.emplace_back(0.003f * i, 0.003f * j, 0.5f);
      cloud.view_masks.push_back(1u);
    }
  }
  return cloud;
}

TEST(OcclusionTest, SpaceBehindASurfaceIsHidden) {
  const OcclusionMap map(wall(), 0.0025f);
  EXPECT_TRUE(map.hidden({0.0f, 0.0f, 0.6f}, 0.01f));
  EXPECT_TRUE(map.hidden({0.05f, -0.05f, 0.52f}, 0.01f));
  EXPECT_FALSE(map.hidden({0.0f, 0.0f, 0.505f}, 0.01f));  // within the margin
  EXPECT_FALSE(map.hidden({0.0f, 0.0f, 0.4f}, 0.01f));    // in front
  EXPECT_FALSE(map.hidden({0.2f, 0.0f, 0.6f}, 0.01f));    // beside the wall
  EXPECT_FALSE(map.hidden({0.0f, 0.0f, -0.6f}, 0.01f));   // behind the sensor
}

TEST(OcclusionTest, SpaceAnotherViewSawIsNotHidden) {
  Cloud cloud = wall();
  // A second view, from the side, saw a post behind the wall.
  cloud.view_origins_m.emplace_back(1.0f, 0.0f, 0.6f);
  for (int j = -10; j <= 10; ++j) {
    cloud.points_m.emplace_back(0.05f, 0.003f * j, 0.6f);
    cloud.view_masks.push_back(2u);
  }
  const OcclusionMap map(cloud, 0.0025f);
  EXPECT_FALSE(map.hidden({0.1f, 0.0f, 0.6f}, 0.01f));   // view 2 sees it in front of the post
  EXPECT_TRUE(map.hidden({-0.05f, 0.0f, 0.6f}, 0.01f));  // behind the post for view 2 too
}

TEST(OcclusionTest, CloudWithoutViewsHidesNothing) {
  Cloud cloud = wall();
  cloud.view_origins_m.clear();
  cloud.view_masks.clear();
  EXPECT_FALSE(OcclusionMap(cloud, 0.0025f).hidden({0.0f, 0.0f, 0.6f}, 0.01f));
}

}  // namespace
}  // namespace antipode
