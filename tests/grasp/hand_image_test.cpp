#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/io/load_cloud.hpp"
#include "synthetic_shapes.hpp"
#include "views.hpp"

namespace antipode {
namespace {

// A hand at a general pose and points placed at known hand coordinates.
struct Placed {
  Cloud cloud;
  Hand hand;
};

Placed placed(const std::vector<Eigen::Vector3d>& in_hand) {
  Placed out;
  out.hand.X_FrameHand = Eigen::Translation3d(0.1, -0.2, 0.7) *
                         Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  for (std::size_t i = 0; i < in_hand.size(); ++i) {
    out.cloud.points_m.push_back((out.hand.X_FrameHand * in_hand[i]).cast<float>());
    out.hand.closing_points.push_back(static_cast<std::int32_t>(i));
  }
  return out;
}

TEST(HandImageTest, PointsLandInThePixelsOfTheirHandCoordinates) {
  // Baxter hand, default options: 1 mm pixels, 60 rows along the approach, 72 columns.
  const Placed p = placed({{0.0105, 0.0005, 0.005}, {0.0595, 0.0355, -0.009}, {0.0305, -0.0355, 0.0}});
  const HandImage image = hand_image(p.cloud, p.hand, HandGeometry{});
  ASSERT_EQ(image.rows, 60);
  ASSERT_EQ(image.cols, 72);
  EXPECT_EQ(image.at(10, 36), 255);
  EXPECT_EQ(image.at(59, 71), 255);
  EXPECT_EQ(image.at(30, 0), 255);
  int set = 0;
  for (const std::uint8_t v : image.pixels) set += v != 0;
  EXPECT_EQ(set, 3);
}

TEST(HandImageTest, DescriptorHasThePapersLayoutAndIsZeroForAnEmptyImage) {
  const HandImageOptions options;
  EXPECT_EQ(options.descriptor_size(), 9u * 11u * 4u * 9u);  // 10 x 12 cells, 2 x 2 blocks
  const Placed empty = placed({});
  const auto zero = hog_descriptor(hand_image(empty.cloud, empty.hand, HandGeometry{}), options);
  ASSERT_EQ(zero.size(), options.descriptor_size());
  for (const float v : zero) EXPECT_EQ(v, 0.0f);
  const Placed one = placed({{0.03, 0.0, 0.0}});
  const auto some = hog_descriptor(hand_image(one.cloud, one.hand, HandGeometry{}), options);
  ASSERT_EQ(some.size(), options.descriptor_size());
  float sum = 0.0f;
  for (const float v : some) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum, 0.0f);
}

TEST(HandImageTest, DescriptorsAreDeterministicForAnyThreadCount) {
  const Cloud cloud = testing::seen_from(
      [](const Eigen::Vector3d& c) {
        return testing::cylinder_cloud(c, Eigen::Vector3d::UnitY(), 0.05, 0.15);
      },
      Eigen::Vector3d::Zero(), {{-0.5, 0.0, 0.3}, {0.5, 0.0, 0.3}});
  HandSamplingOptions sampling;
  sampling.search.samples = 100;
  const HandSet set = sample_hands(cloud, sampling, RandomStream(2));
  ASSERT_GT(set.hands.size(), 20u);
  const auto one = hand_descriptors(set, HandGeometry{}, {}, 1);
  const auto two = hand_descriptors(set, HandGeometry{}, {}, 2);
  ASSERT_EQ(one.size(), set.hands.size());
  EXPECT_EQ(one, two);
  for (std::size_t i = 0; i < set.hands.size(); i += 7) {
    EXPECT_EQ(one[i], hog_descriptor(hand_image(*set.cloud, set.hands[i], HandGeometry{})));
  }
}

TEST(HandImageTest, InvalidInputIsAnError) {
  Placed p = placed({{0.03, 0.0, 0.0}});
  HandImageOptions options;
  options.block_cells = 20;
  EXPECT_THROW(hand_image(p.cloud, p.hand, HandGeometry{}, options), Error);
  options = {};
  options.cell_px = 0;
  EXPECT_THROW(options.validate(), Error);
  HandImage wrong;
  wrong.rows = 10;
  wrong.cols = 10;
  wrong.pixels.assign(100, 0);
  EXPECT_THROW(hog_descriptor(wrong), Error);
  p.hand.closing_points.push_back(5);
  EXPECT_THROW(hand_image(p.cloud, p.hand, HandGeometry{}), Error);
  HandSet set;
  set.hands.push_back(p.hand);
  EXPECT_THROW(hand_descriptors(set, HandGeometry{}), Error);  // no cloud
}

// Descriptors of the hypotheses of a real cloud (skipped without ../shared/data); prints the
// time they take.
TEST(HandImageTest, DescriptorsOnTableMug) {
  const std::string path = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  HandSamplingOptions sampling;
  sampling.search.samples = 4000;
  sampling.search.threads = 2;
  const HandSet set = sample_hands(load_cloud(path), sampling, RandomStream(1));
  ASSERT_GT(set.hands.size(), 1000u);
  const auto start = std::chrono::steady_clock::now();
  const auto descriptors = hand_descriptors(set, HandGeometry{}, {}, 2);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("hand_descriptors: %zu hands in %.1f ms\n", descriptors.size(), 1e3 * seconds);
  EXPECT_EQ(descriptors.size(), set.hands.size());
  EXPECT_LT(seconds, 5.0);
}

}  // namespace
}  // namespace antipode
