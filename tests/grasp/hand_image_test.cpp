#include <cmath>
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
  const Placed p =
      placed({{0.0105, 0.0005, 0.005}, {0.0595, 0.0355, -0.009}, {0.0305, -0.0355, 0.0}});
  HandImageOptions single_pixels;
  single_pixels.point_radius_px = 0;
  const HandImage image = hand_image(p.cloud, p.hand, HandGeometry{}, single_pixels);
  ASSERT_EQ(image.rows, 60);
  ASSERT_EQ(image.cols, 72);
  EXPECT_EQ(image.at(10, 36), 255);
  EXPECT_EQ(image.at(59, 71), 255);
  EXPECT_EQ(image.at(30, 0), 255);
  int set = 0;
  for (const std::uint8_t v : image.pixels) set += v != 0;
  EXPECT_EQ(set, 3);
}

TEST(HandImageTest, PointsAreDrawnAsDiscsClippedAtTheBorder) {
  const Placed p = placed({{0.0305, 0.0005, 0.0}, {0.0005, -0.0355, 0.0}});
  const HandImage image = hand_image(p.cloud, p.hand, HandGeometry{});  // radius 2 px
  int set = 0;
  for (const std::uint8_t v : image.pixels) set += v != 0;
  // 13 pixels within 2 px of the inner point; a quarter disc (6 pixels) at the corner.
  EXPECT_EQ(set, 13 + 6);
  EXPECT_EQ(image.at(30, 38), 255);
  EXPECT_EQ(image.at(32, 36), 255);
  EXPECT_EQ(image.at(32, 38), 0);
}

TEST(HandImageTest, AHandTurnedAboutItsApproachSeesTheImageMirrored) {
  // Points off the pixel borders, so that mirroring y maps each to the mirrored column.
  const std::vector<Eigen::Vector3d> in_hand = {
      {0.0105, 0.0204, 0.005}, {0.0402, -0.0303, -0.004}, {0.0555, 0.0011, 0.0}};
  const Placed p = placed(in_hand);
  Hand turned = p.hand;
  turned.X_FrameHand = p.hand.X_FrameHand * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
  const HandImage image = hand_image(p.cloud, p.hand, HandGeometry{});
  const HandImage mirrored = hand_image(p.cloud, turned, HandGeometry{});
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      ASSERT_EQ(image.at(r, c), mirrored.at(r, image.cols - 1 - c)) << r << ", " << c;
    }
  }
  // The normal statistics: blocks mirrored, n . closing negated, |n . axis| kept.
  std::vector<Eigen::Vector3f> normals(p.cloud.size());
  for (std::size_t i = 0; i < normals.size(); ++i) {
    normals[i] =
        (p.hand.X_FrameHand.linear() * Eigen::Vector3d(0.3, 0.8, -0.52).normalized()).cast<float>();
  }
  const HandImageOptions options;
  const auto a = normal_statistics(p.cloud, p.hand, HandGeometry{}, options, normals);
  const auto b = normal_statistics(p.cloud, turned, HandGeometry{}, options, normals);
  ASSERT_EQ(a.size(), options.normal_features_size());
  const int across = 6;  // blocks of 2 x 2 cells across 12 cells
  const std::size_t blocks = 5 * 6;
  for (std::size_t block = 0; block < blocks; ++block) {
    const std::size_t row = block / across, col = block % across;
    const std::size_t other = row * across + (across - 1 - col);
    EXPECT_NEAR(a[3 * block], -b[3 * other], 1e-6);
    EXPECT_NEAR(a[3 * block + 1], b[3 * other + 1], 1e-6);
    EXPECT_NEAR(a[3 * block + 2], b[3 * other + 2], 1e-6);
  }
  // The alignment counts (six angles per side): +closing and -closing swap.
  const std::size_t angles = (a.size() - 3 * blocks - 5) / 2;
  ASSERT_EQ(angles, 6u);
  for (std::size_t k = 0; k < angles; ++k) {
    EXPECT_EQ(a[3 * blocks + k], b[3 * blocks + angles + k]);
    EXPECT_EQ(a[3 * blocks + angles + k], b[3 * blocks + k]);
  }
}

TEST(HandImageTest, NormalStatisticsAverageEachBlock) {
  // Two points in the block at the palm's -y corner, one in the middle block of the tips.
  const Placed p = placed({{0.001, -0.035, 0.0}, {0.002, -0.034, 0.0}, {0.059, 0.001, 0.0}});
  const Eigen::Matrix3d R = p.hand.X_FrameHand.linear();
  const std::vector<Eigen::Vector3f> normals = {(R * Eigen::Vector3d(0, 1, 0)).cast<float>(),
                                                (R * Eigen::Vector3d(0, 0.6, 0.8)).cast<float>(),
                                                Eigen::Vector3f::Zero()};  // no normal: not counted
  const HandImageOptions options;
  const auto f = normal_statistics(p.cloud, p.hand, HandGeometry{}, options, normals);
  ASSERT_EQ(f.size(), 3u * 5u * 6u + 12u + 5u);
  EXPECT_NEAR(f[0], 4.0 * (1.0 + 0.6) / 2.0, 1e-5);  // mean n . closing
  EXPECT_NEAR(f[1], 4.0 * (0.0 + 0.8) / 2.0, 1e-5);  // mean |n . axis|
  EXPECT_NEAR(f[2], 4.0 * std::log1p(2.0) / std::log1p(64.0), 1e-5);
  const std::size_t tip = 3 * (4 * 6 + 3);  // last block row, column 36 -> block 3
  EXPECT_EQ(f[tip + 2], 0.0f);
  float others = 0.0f;
  for (std::size_t i = 3; i < 3u * 5u * 6u; ++i) others += std::abs(f[i]);
  EXPECT_EQ(others, 0.0f);
}

TEST(HandImageTest, AlignmentCountsFollowDefinition3sAngles) {
  // Normals at 5, 12, 22, 27, 40 and 60 degrees from +closing, one at 17 degrees from -closing.
  std::vector<Eigen::Vector3d> in_hand;
  for (int i = 0; i < 7; ++i) in_hand.emplace_back(0.01 + 0.007 * i, 0.0, 0.0);
  const Placed p = placed(in_hand);
  const Eigen::Matrix3d R = p.hand.X_FrameHand.linear();
  const auto at = [&](double degrees, double side) {
    const double a = degrees * M_PI / 180.0;
    return (R * Eigen::Vector3d(std::sin(a), side * std::cos(a), 0.0)).cast<float>().eval();
  };
  const std::vector<Eigen::Vector3f> normals = {at(5, 1),  at(12, 1), at(22, 1), at(27, 1),
                                                at(40, 1), at(60, 1), at(17, -1)};
  const HandImageOptions options;
  const auto f = normal_statistics(p.cloud, p.hand, HandGeometry{}, options, normals);
  ASSERT_EQ(f.size(), options.normal_features_size());
  ASSERT_EQ(f.size(), 3u * 5u * 6u + 12u + 5u);
  const auto log_count = [](int k) { return 12.0 * std::log1p(k) / std::log1p(64.0); };
  const std::size_t first = 3 * 5 * 6;
  // Within 10, 15, 20, 25, 30, 45 degrees of +closing: 1, 2, 2, 3, 4, 5 points; of -closing:
  // 0, 0, 1, 1, 1, 1.
  const std::vector<int> expected = {1, 2, 2, 3, 4, 5, 0, 0, 1, 1, 1, 1};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_NEAR(f[first + k], log_count(expected[k]), 1e-5) << k;
  }
}

// A wall of points 1 m in front of a sensor at the origin, facing it (the plane x = 1), and
// a hand whose closing direction is +x (from the sensor into the wall) and whose closing
// region is centred on the wall.
struct WallAndHand {
  Cloud cloud;
  Hand hand;
};

WallAndHand wall_and_hand() {
  WallAndHand out;
  for (int i = -50; i <= 50; ++i) {
    for (int j = -50; j <= 50; ++j) out.cloud.points_m.emplace_back(1.0f, 0.002f * i, 0.002f * j);
  }
  out.cloud.view_origins_m.push_back(Eigen::Vector3f::Zero());
  out.cloud.view_masks.assign(out.cloud.size(), 1u);
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d::UnitY();   // approach
  R.col(1) = Eigen::Vector3d::UnitX();   // closing: away from the sensor
  R.col(2) = -Eigen::Vector3d::UnitZ();  // axis
  out.hand.X_FrameHand = Eigen::Translation3d(1.0, -0.03, 0.0) * Eigen::Quaterniond(R);
  return out;
}

TEST(HandImageTest, OcclusionStatisticsMarkTheRegionBehindTheSeenSurface) {
  const WallAndHand w = wall_and_hand();
  const HandImageOptions options;
  const OcclusionMap occlusion(w.cloud, 0.0025f);
  const auto f = occlusion_statistics(occlusion, w.hand, HandGeometry{}, options);
  ASSERT_EQ(f.size(), options.occlusion_features_size());
  ASSERT_EQ(f.size(), 5u * 6u);  // blocks of 2 x 2 cells over 10 x 12 cells
  for (int row = 0; row < 5; ++row) {
    // Block columns 0-2 lie in front of the wall (seen to be empty), 4-5 behind it; column 3
    // holds the wall itself.
    for (int col : {0, 1, 2}) EXPECT_FLOAT_EQ(f[row * 6 + col], 0.0f) << row << ", " << col;
    for (int col : {4, 5}) EXPECT_FLOAT_EQ(f[row * 6 + col], 4.0f) << row << ", " << col;
  }
  // The same hand closing the other way round sees the hidden side mirrored.
  Hand turned = w.hand;
  turned.X_FrameHand = w.hand.X_FrameHand * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
  const auto g = occlusion_statistics(occlusion, turned, HandGeometry{}, options);
  for (int row = 0; row < 5; ++row) {
    for (int col = 0; col < 6; ++col) EXPECT_FLOAT_EQ(g[row * 6 + col], f[row * 6 + 5 - col]);
  }
  // Without a sensor origin nothing is known to be hidden.
  Cloud unknown = w.cloud;
  unknown.view_origins_m.clear();
  unknown.view_masks.clear();
  for (const float v :
       occlusion_statistics(OcclusionMap(unknown, 0.0025f), w.hand, HandGeometry{}, options)) {
    EXPECT_EQ(v, 0.0f);
  }
}

// The wall's points in the hand's closing region, with their outward normal (towards the
// sensor at the origin: -x).
std::vector<Eigen::Vector3f> closing_region_with_normals(WallAndHand& w) {
  const HandGeometry g;
  const Eigen::Isometry3d X_HandFrame = w.hand.X_FrameHand.inverse();
  for (std::size_t i = 0; i < w.cloud.size(); ++i) {
    const Eigen::Vector3d q = X_HandFrame * w.cloud.points_m[i].cast<double>();
    if (q.x() >= 0.0 && q.x() <= g.depth_m && std::abs(q.y()) <= g.max_aperture_m / 2.0 &&
        std::abs(q.z()) <= g.height_m / 2.0) {
      w.hand.closing_points.push_back(static_cast<std::int32_t>(i));
    }
  }
  return std::vector<Eigen::Vector3f>(w.cloud.size(), -Eigen::Vector3f::UnitX());
}

TEST(HandImageTest, ViewStatisticsTellAFaceOnViewFromAGrazingOne) {
  WallAndHand w = wall_and_hand();
  std::vector<Eigen::Vector3f> normals = closing_region_with_normals(w);
  ASSERT_GT(w.hand.closing_points.size(), 100u);
  // Seen face on: the surface faces the -y finger (n = -closing) and the sensor (n . u ~ 1);
  // the sensor lies along -closing, across the approach and the axis.
  const auto face_on = view_statistics(w.cloud, w.hand, normals);
  ASSERT_EQ(face_on.size(), 5u);
  EXPECT_EQ(face_on[0], 0.0f);  // nothing faces the +y finger
  EXPECT_NEAR(face_on[1], 4.0, 0.01);
  EXPECT_NEAR(face_on[2], 0.0, 0.01);
  EXPECT_NEAR(face_on[3], -4.0, 0.01);
  EXPECT_NEAR(face_on[4], 0.0, 0.01);
  // Seen 60 degrees off its normal, towards +z (the hand axis is -z): n . u ~ cos 60.
  WallAndHand oblique = w;
  oblique.cloud.view_origins_m[0] = Eigen::Vector3f(0.5f, 0.0f, 0.866f);
  const auto grazing = view_statistics(oblique.cloud, oblique.hand, normals);
  EXPECT_NEAR(grazing[1], 4.0 * 0.5, 0.05);
  EXPECT_NEAR(grazing[3], -4.0 * 0.5, 0.05);
  EXPECT_NEAR(grazing[4], -4.0 * 0.866, 0.05);
  // A hand turned half a turn about its approach: the sides swap, closing and axis negate.
  Hand turned = oblique.hand;
  turned.X_FrameHand = oblique.hand.X_FrameHand * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX());
  const auto mirrored = view_statistics(oblique.cloud, turned, normals);
  EXPECT_NEAR(mirrored[0], grazing[1], 1e-6);
  EXPECT_NEAR(mirrored[1], grazing[0], 1e-6);
  EXPECT_NEAR(mirrored[2], grazing[2], 1e-6);
  EXPECT_NEAR(mirrored[3], -grazing[3], 1e-6);
  EXPECT_NEAR(mirrored[4], -grazing[4], 1e-6);
  // Points without a normal count for neither side, and add nothing to the mean direction.
  for (std::size_t k = 0; k < w.hand.closing_points.size(); k += 2) {
    normals[static_cast<std::size_t>(w.hand.closing_points[k])].setZero();
  }
  const auto half = view_statistics(w.cloud, w.hand, normals);
  EXPECT_NEAR(half[1], face_on[1], 1e-3);
  EXPECT_NEAR(half[3], face_on[3] / 2.0, 0.05);
  // A cloud without view origins: nothing is known of the sensors.
  Cloud unknown = w.cloud;
  unknown.view_origins_m.clear();
  unknown.view_masks.clear();
  for (const float v : view_statistics(unknown, w.hand, normals)) EXPECT_EQ(v, 0.0f);
  EXPECT_THROW(view_statistics(w.cloud, w.hand, {}), Error);
}

TEST(HandImageTest, DescriptorHasThePapersLayoutAndIsZeroForAnEmptyImage) {
  HandImageOptions options;
  EXPECT_EQ(options.hog_size(), 9u * 11u * 4u * 9u);  // 10 x 12 cells, 2 x 2 blocks
  EXPECT_EQ(options.descriptor_size(), options.hog_size() + 90u + 12u + 5u + 30u);
  options.occlusion_features = false;
  EXPECT_EQ(options.descriptor_size(), options.hog_size() + 90u + 12u + 5u);
  options.normal_features = false;
  EXPECT_EQ(options.descriptor_size(), options.hog_size());
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
    const auto hog = hog_descriptor(hand_image(*set.cloud, set.hands[i], HandGeometry{}));
    EXPECT_EQ(std::vector<float>(one[i].begin(), one[i].begin() + hog.size()), hog);
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

// Descriptors of the hypotheses of a real cloud (skipped without ../shared/data); their time
// is measured by bench/classification_bench.
TEST(HandImageTest, DescriptorsOnTableMug) {
  const std::string path = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  HandSamplingOptions sampling;
  sampling.search.samples = 4000;
  sampling.search.threads = 2;
  const HandSet set = sample_hands(load_cloud(path), sampling, RandomStream(1));
  ASSERT_GT(set.hands.size(), 1000u);
  const auto descriptors = hand_descriptors(set, HandGeometry{}, {}, 2);
  ASSERT_EQ(descriptors.size(), set.hands.size());
  const HandImageOptions options;
  const std::size_t occlusion_first = options.hog_size() + options.normal_features_size();
  std::size_t some_hidden = 0;
  for (const auto& d : descriptors) {
    ASSERT_EQ(d.size(), options.descriptor_size());
    float hidden = 0.0f;
    for (std::size_t k = occlusion_first; k < d.size(); ++k) hidden += d[k];
    some_hidden += hidden > 0.0f ? 1 : 0;
  }
  // The cloud is one view of a table and a mug: most hands reach behind a seen surface.
  EXPECT_GT(some_hidden, descriptors.size() / 2);
}

}  // namespace
}  // namespace antipode
