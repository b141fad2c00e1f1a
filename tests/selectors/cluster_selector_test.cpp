#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "antipode/core/error.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "closing_tilt.hpp"
#include "contact_depth.hpp"
#include "finger_cover.hpp"
#include "hand_clearance.hpp"
#include "hand_clusters.hpp"
#include "held_width.hpp"

namespace antipode {
namespace {

using selectors::ClusterOptions;

// A hand approaching straight down (x = -z), closing along +y, palm face at (x, y, z).
Hand top_down(double x, double y, double z, double score = 1.0, double width = 0.05) {
  Hand hand;
  Eigen::Matrix3d r;
  r.col(0) = -Eigen::Vector3d::UnitZ();
  r.col(1) = Eigen::Vector3d::UnitY();
  r.col(2) = r.col(0).cross(r.col(1));
  hand.X_FrameHand.linear() = r;
  hand.X_FrameHand.translation() << x, y, z;
  hand.score = score;
  hand.width_m = width;
  hand.label = HandLabel::kPositive;
  return hand;
}

// The same hand turned about the vertical by `yaw_deg`.
Hand turned(Hand hand, double yaw_deg) {
  hand.X_FrameHand.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
                              hand.X_FrameHand.linear();
  return hand;
}

// A set over an empty cloud (nothing blocks any approach) with a table at z = 0.
HandSet on_table(std::vector<Hand> hands) {
  HandSet set;
  set.cloud = std::make_shared<Cloud>();
  set.hands = std::move(hands);
  set.support = SupportPlane{Eigen::Vector3f::UnitZ(), 0.0f, 0};
  return set;
}

class ClusterSelectorTest : public ::testing::Test {
 protected:
  ClusterSelectorTest() : host_(std::vector<std::string>{}) {
    host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" +
                       plugin_file_name("cluster_selector"));
  }

  std::shared_ptr<GraspSelector> create(const std::string& yaml) {
    const Parameters params(YAML::Load(yaml), "component 'selector'", "tree.yaml");
    return std::dynamic_pointer_cast<GraspSelector>(host_.create("cluster_selector", params));
  }

  std::string creation_error(const std::string& yaml) {
    try {
      create(yaml);
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  }

  PluginHost host_;
};

std::size_t grasp_count(const HandSet& selection) {
  std::size_t n = 0;
  while (n < selection.hands.size() && selection.hands[n].rejection == Rejection::kNone) ++n;
  return n;
}

TEST(HandClusters, SimilarHandsUpToTheClosingSign) {
  const ClusterOptions options{0.02, 20.0};
  const Hand a = top_down(0.0, 0.0, 0.1);
  EXPECT_TRUE(selectors::similar(a, top_down(0.01, 0.0, 0.1), options));
  EXPECT_FALSE(selectors::similar(a, top_down(0.03, 0.0, 0.1), options));
  EXPECT_TRUE(selectors::similar(a, turned(a, 15.0), options));
  EXPECT_FALSE(selectors::similar(a, turned(a, 30.0), options));
  EXPECT_TRUE(selectors::similar(a, turned(a, 180.0), options)) << "a half turn is the same grasp";
  Hand on_another = top_down(0.005, 0.0, 0.1);
  on_another.object = 3;  // a neighbour a few millimetres away: never averaged with `a`
  EXPECT_FALSE(selectors::similar(a, on_another, options));
}

TEST(HandClusters, TheMeanGraspAveragesPositionsAndRotations) {
  const std::vector<Hand> hands = {top_down(0.0, 0.0, 0.1, 2.0, 0.04),
                                   turned(top_down(0.01, 0.0, 0.1, 1.0, 0.05), 190.0),
                                   turned(top_down(0.02, 0.0, 0.1, 1.0, 0.045), -10.0)};
  const Hand mean = selectors::mean_hand(hands, {0, 1, 2});
  EXPECT_NEAR(mean.position_m().x(), 0.01, 1e-12);
  EXPECT_NEAR(mean.approach().z(), -1.0, 1e-9);
  // Closing directions at 0, 10 (190 turned back by half a turn) and -10 degrees: mean 0.
  EXPECT_NEAR(mean.closing().y(), 1.0, 1e-9);
  EXPECT_NEAR((mean.X_FrameHand.linear().transpose() * mean.X_FrameHand.linear() -
               Eigen::Matrix3d::Identity())
                  .norm(),
              0.0, 1e-9);
  EXPECT_DOUBLE_EQ(mean.width_m, 0.05) << "the widest member";
  EXPECT_DOUBLE_EQ(mean.score, 4.0) << "the members' scores add up";
}

TEST(HandClearance, TheWayInMustStayAboveTheSupport) {
  const HandGeometry g;  // fingers 6 cm, palm 2 cm, half height 1 cm
  const SupportPlane table{Eigen::Vector3f::UnitZ(), 0.0f, 0};
  // Top down: the fingertips are the lowest corners, 6 cm below the palm face.
  EXPECT_TRUE(selectors::clears_support(top_down(0, 0, 0.07, 1), g, table, 0.1, 0.005));
  EXPECT_FALSE(selectors::clears_support(top_down(0, 0, 0.062, 1), g, table, 0.1, 0.005));
  // Approaching horizontally along +x, 2 cm above the table: the 2 cm high hand's lower
  // face is 1 cm up on the whole way in.
  Hand side = top_down(0, 0, 0.02);
  side.X_FrameHand.linear().setIdentity();
  EXPECT_TRUE(selectors::clears_support(side, g, table, 0.1, 0.005));
  // Approaching 17 degrees upwards to a pose 3 cm above the table: the pose clears it by
  // 1.5 cm, the stand-off pose 10 cm back is below the table.
  Hand rising = top_down(0, 0, 0.03);
  rising.X_FrameHand.linear() = Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitY()).matrix();
  ASSERT_GT(rising.approach().z(), 0.29);
  EXPECT_FALSE(selectors::clears_support(rising, g, table, 0.1, 0.005));
  EXPECT_TRUE(selectors::clears_support(rising, g, table, 0.0, 0.005))
      << "without a stand-off only the pose itself counts";
}

TEST(HandClearance, PointsOnTheWayInBlockIt) {
  const HandGeometry g;
  const Hand hand = top_down(0, 0, 0.1);  // palm face at 10 cm, fingertips at 4 cm
  Cloud cloud;
  cloud.points_m = {Eigen::Vector3f(0, 0, 0.06)};  // between the fingers: the object
  EXPECT_TRUE(selectors::approach_is_free(hand, g, cloud, 0.1));
  cloud.points_m.emplace_back(0, 0, 0.15);  // 5 cm above the palm face, under the stand-off
  EXPECT_FALSE(selectors::approach_is_free(hand, g, cloud, 0.1));
  EXPECT_TRUE(selectors::approach_is_free(hand, g, cloud, 0.02)) << "a shorter stand-off";
  cloud.points_m = {Eigen::Vector3f(0, 0.04, 0.06)};  // in the +y finger
  EXPECT_FALSE(selectors::approach_is_free(hand, g, cloud, 0.1));
}

TEST_F(ClusterSelectorTest, ClustersHandsIntoOneMeanGraspAndKeepsEveryReason) {
  const auto selector = create("min_cluster_size: 2");
  std::vector<Hand> hands = {top_down(0.0, 0.0, 0.1, 1.0), top_down(0.005, 0.0, 0.1, 2.0),
                             top_down(0.3, 0.0, 0.1, 3.0), top_down(0.0, 0.2, 0.1, 1.0)};
  hands[3].rejection = Rejection::kNotAntipodal;
  const HandSet selection = selector->select(on_table(hands), {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_NEAR(selection.hands[0].position_m().x(), 0.0025, 1e-12);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 3.0);
  EXPECT_FALSE(selection.hands[0].closing_points.size() > 0) << "the cloud is empty";
  ASSERT_EQ(selection.hands.size(), 1u + hands.size()) << "the grasp, then every input hand";
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kClustered);
  EXPECT_EQ(selection.hands[1].merged_into, 0);
  EXPECT_EQ(selection.hands[2].rejection, Rejection::kClustered);
  EXPECT_EQ(selection.hands[3].rejection, Rejection::kSmallCluster) << "alone at x = 0.3";
  EXPECT_EQ(selection.hands[4].rejection, Rejection::kNotAntipodal) << "earlier reasons stay";
}

TEST_F(ClusterSelectorTest, DropsHandsBelowTheSupportOrOutsideTheAperture) {
  const auto selector = create("min_cluster_size: 1");
  const HandSet selection =
      selector->select(on_table({top_down(0, 0, 0.05), top_down(0.2, 0, 0.1, 1.0, 0.08),
                                 top_down(0.4, 0, 0.1, 1.0, 0.02), top_down(0.6, 0, 0.1)}),
                       {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_NEAR(selection.hands[0].position_m().x(), 0.6, 1e-12);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kBelowSupport) << "fingertips at -1 cm";
  EXPECT_EQ(selection.hands[2].rejection, Rejection::kApertureLimit) << "8 cm: wider than open";
  EXPECT_EQ(selection.hands[3].rejection, Rejection::kApertureLimit) << "2 cm: under closed";
}

TEST_F(ClusterSelectorTest, TheApertureCriterionRanksBeforeTheScore) {
  const auto selector = create("min_cluster_size: 1\nmax_grasps: 3");
  const HandSet selection =
      selector->select(on_table({top_down(0, 0, 0.1, 9.0, 0.071), top_down(0.2, 0, 0.1, 1.0, 0.05),
                                 top_down(0.4, 0, 0.1, 2.0, 0.066)}),
                       {});  // 6.6 cm: 6 mm from the limit, no penalty
  ASSERT_EQ(grasp_count(selection), 3u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 2.0);
  EXPECT_DOUBLE_EQ(selection.hands[1].score, 1.0);
  EXPECT_DOUBLE_EQ(selection.hands[2].score, 9.0) << "1 mm from the open gripper ranks last";
}

// A 2.7 cm neck between the fingers of top_down(x, 0, z): 100 points evenly over its width
// 3 cm below the palm face, and `strays` points each side 3 cm out (depth errors at its
// silhouette), in `cloud`; the hand's closing points and full extent set from them.
Hand over_neck(double x, double z, int strays, Cloud& cloud) {
  Hand hand = top_down(x, 0.0, z);
  hand.closing_points.clear();
  const auto add = [&](double y) {
    cloud.points_m.emplace_back(float(x), float(y), float(z - 0.03));
    hand.closing_points.push_back(std::int32_t(cloud.size() - 1));
  };
  for (int i = 0; i < 100; ++i) add(-0.0135 + 0.027 * i / 99.0);
  for (int i = 0; i < strays; ++i) add(-0.03), add(0.03);
  hand.width_m = strays > 0 ? 0.06 : 0.027;
  return hand;
}

TEST(HeldWidth, TrimsStrayPointsAlongTheClosingDirection) {
  Cloud cloud;
  std::vector<float> scratch;
  const Hand hand = over_neck(0.0, 0.1, 2, cloud);
  EXPECT_NEAR(selectors::held_width_m(hand, cloud, 0.0, 0.0, scratch), 0.06, 1e-6);
  // 5% of 104 points trimmed each side: both strays and three of the neck's own; the bulk
  // scaled back by 1 / 0.9.
  EXPECT_NEAR(selectors::held_width_m(hand, cloud, 0.05, 0.0, scratch), 0.027, 1.5e-3);
  // On evenly spread points alone the full extent comes back.
  Cloud clean;
  EXPECT_NEAR(selectors::held_width_m(over_neck(0.0, 0.1, 0, clean), clean, 0.05, 0.0, scratch),
              0.027, 1e-3);
  Hand made_by_hand = top_down(0, 0, 0.1, 1.0, 0.045);
  EXPECT_DOUBLE_EQ(selectors::held_width_m(made_by_hand, cloud, 0.05, 0.0, scratch), 0.045);
}

// A plate `thickness_m` thick with unit normal `normal_hand` (hand coordinates of
// top_down(0, 0, 0): x = approach, y = closing, z = axis), both faces sampled every 2 mm
// where they cross the closing region (x in [0.5, 5.5] cm, |y| < 3.6 cm, |z| <= 1 cm), into
// `cloud`; the hand's closing points and width set from them.
Hand across_plate(const Eigen::Vector3d& normal_hand, double thickness_m, Cloud& cloud) {
  Hand hand = top_down(0.0, 0.0, 0.0);
  const Eigen::Vector3d n = normal_hand.normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  double low = 1.0, high = -1.0;
  for (const double side : {-0.5, 0.5}) {
    for (int i = -60; i <= 60; ++i) {
      for (int j = -60; j <= 60; ++j) {
        const Eigen::Vector3d p =
            Eigen::Vector3d(0.03, 0, 0) + side * thickness_m * n + 0.002 * i * u + 0.002 * j * v;
        if (p.x() < 0.005 || p.x() > 0.055 || std::abs(p.y()) >= 0.036 || std::abs(p.z()) > 0.01)
          continue;
        cloud.points_m.push_back((hand.X_FrameHand * p).cast<float>());
        hand.closing_points.push_back(std::int32_t(cloud.size() - 1));
        low = std::min(low, p.y()), high = std::max(high, p.y());
      }
    }
  }
  hand.width_m = high - low;
  return hand;
}

TEST(HeldWidth, APlateSeenOnItsTwoFacesKeepsItsThickness) {
  Cloud cloud;
  std::vector<float> scratch;
  const Hand hand = across_plate(Eigen::Vector3d::UnitY(), 0.026, cloud);
  // The trimmed extent scaled back by 1 / 0.9 would pass it for 2.9 cm.
  EXPECT_NEAR(selectors::held_width_m(hand, cloud, 0.05, 20.0, scratch), 0.026, 1e-4);
}

TEST(HeldWidth, TheSqueezeTurnsALeaningPlateToItsThickness) {
  std::vector<float> scratch;
  const double a = 16.0 * M_PI / 180.0;
  // Turned about the approach axis (a bar lying across the fingers' tips from above) and
  // about the hand axis (a plate leaning across the closing direction).
  for (const Eigen::Vector3d& normal : {Eigen::Vector3d(0, std::cos(a), std::sin(a)),
                                        Eigen::Vector3d(std::sin(a), std::cos(a), 0)}) {
    Cloud cloud;
    const Hand hand = across_plate(normal, 0.026, cloud);
    EXPECT_GT(selectors::held_width_m(hand, cloud, 0.05, 0.0, scratch), 0.031) << normal;
    EXPECT_NEAR(selectors::held_width_m(hand, cloud, 0.05, 20.0, scratch), 0.026, 1e-3) << normal;
    // Not beyond the turn allowed: 8 degrees leave it wider.
    EXPECT_GT(selectors::held_width_m(hand, cloud, 0.05, 8.0, scratch), 0.028) << normal;
  }
  // A plate square to the fingers does not turn: its width is its thickness.
  Cloud square;
  const Hand hand = across_plate(Eigen::Vector3d::UnitY(), 0.05, square);
  EXPECT_NEAR(selectors::held_width_m(hand, square, 0.05, 20.0, scratch), 0.05, 1e-4);
}

TEST_F(ClusterSelectorTest, ALeaningPlateThinnerThanTheClosedGripperIsNotAGrasp) {
  auto cloud = std::make_shared<Cloud>();
  const double a = 16.0 * M_PI / 180.0;
  Hand diagonal = across_plate(Eigen::Vector3d(0, std::cos(a), std::sin(a)), 0.026, *cloud);
  diagonal.X_FrameHand.translation() << 0, 0, 0.1;
  for (auto& p : cloud->points_m) p.z() += 0.1f;
  HandSet set = on_table({diagonal, top_down(0.3, 0, 0.1, 0.5, 0.05)});
  set.cloud = cloud;
  const HandSet squeezed = create("min_cluster_size: 1\nunseen_is_free: true")->select(set, {});
  ASSERT_EQ(grasp_count(squeezed), 1u);
  EXPECT_NEAR(squeezed.hands[0].position_m().x(), 0.3, 1e-12);
  EXPECT_EQ(squeezed.hands[1].rejection, Rejection::kApertureLimit);
  const HandSet unturned =
      create("min_cluster_size: 1\nunseen_is_free: true\nsqueeze_turn_deg: 0")->select(set, {});
  EXPECT_EQ(grasp_count(unturned), 2u) << to_string(unturned.hands[1].rejection);
}

TEST_F(ClusterSelectorTest, ANeckNarrowerThanTheClosedGripperIsNotAGraspWhateverItsStrays) {
  // Full extent 6 cm (inside the 3-7.2 cm aperture), the neck itself 2.7 cm: the fingers
  // would close on nothing.
  auto cloud = std::make_shared<Cloud>();
  HandSet set = on_table({over_neck(0.0, 0.1, 2, *cloud), top_down(0.3, 0, 0.1, 0.5, 0.05)});
  set.cloud = cloud;
  const HandSet trimmed = create("min_cluster_size: 1\nunseen_is_free: true")->select(set, {});
  ASSERT_EQ(grasp_count(trimmed), 1u);
  EXPECT_NEAR(trimmed.hands[0].position_m().x(), 0.3, 1e-12);
  EXPECT_EQ(trimmed.hands[1].rejection, Rejection::kApertureLimit);
  // Judged on the full extent, as before width_trim, the neck is the better-scored grasp (its
  // points, on one line, fill none of the fingers' height: that check is off here).
  const HandSet full =
      create("min_cluster_size: 1\nunseen_is_free: true\nwidth_trim: 0\nmin_finger_cover: 0")
          ->select(set, {});
  ASSERT_EQ(grasp_count(full), 2u);
  EXPECT_NEAR(full.hands[0].position_m().x(), 0.0, 1e-12);
}

// A 5 cm block's two side faces where they cross the closing region of top_down(0, 0, 0.1),
// sampled every 2 mm, only for hand-axis coordinates z in [z_low, z_high] (the fingers span
// |z| <= 1 cm): the block fills that band of the fingers' height.
Hand across_band(double z_low, double z_high, Cloud& cloud) {
  Hand hand = top_down(0.0, 0.0, 0.1);
  for (const double y : {-0.025, 0.025})
    for (double x = 0.005; x <= 0.055; x += 0.002)
      for (double z = z_low; z <= z_high + 1e-9; z += 0.002) {
        cloud.points_m.push_back((hand.X_FrameHand * Eigen::Vector3d(x, y, z)).cast<float>());
        hand.closing_points.push_back(std::int32_t(cloud.size() - 1));
      }
  return hand;
}

TEST(FingerCover, TheShareOfTheFingersHeightTheObjectFills) {
  const HandGeometry gripper;  // fingers 2 cm tall
  std::vector<float> scratch;
  Cloud full, rim;
  EXPECT_NEAR(selectors::finger_cover(across_band(-0.01, 0.01, full), full, gripper, 0.05, scratch),
              1.0, 1e-6);
  // Only the lowest 4 mm: the fingers pass over the object's edge.
  EXPECT_NEAR(selectors::finger_cover(across_band(-0.01, -0.006, rim), rim, gripper, 0.05, scratch),
              0.2, 1e-6);
  EXPECT_DOUBLE_EQ(selectors::finger_cover(top_down(0, 0, 0.1), full, gripper, 0.05, scratch), 1.0);
}

TEST_F(ClusterSelectorTest, FingersThatOnlyClipAnEdgeAreNotAGrasp) {
  auto cloud = std::make_shared<Cloud>();
  const Hand full = across_band(-0.01, 0.01, *cloud);
  Hand rim = across_band(-0.01, -0.006, *cloud);
  rim.X_FrameHand.translation().x() = 0.3;
  for (const std::int32_t i : rim.closing_points) cloud->points_m[std::size_t(i)].x() += 0.3f;
  rim.score = 2.0;  // the better score
  HandSet set = on_table({rim, full});
  set.cloud = cloud;
  const std::string base = "min_cluster_size: 1\nunseen_is_free: true\n";
  const HandSet selection = create(base)->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_NEAR(selection.hands[0].position_m().x(), 0.0, 1e-12);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kFingersOverAnEdge);
  EXPECT_STREQ(to_string(Rejection::kFingersOverAnEdge), "fingers over an edge");
  const HandSet unchecked = create(base + "min_finger_cover: 0")->select(set, {});
  ASSERT_EQ(grasp_count(unchecked), 2u);
  EXPECT_NEAR(unchecked.hands[0].position_m().x(), 0.3, 1e-12);
}

// A ball of radius 3 cm centred `centre_x_m` along the approach of top_down(0, 0, 0.1), its
// surface sampled about every mm where it crosses the closing region, into `cloud`.
Hand around_ball(double centre_x_m, Cloud& cloud) {
  Hand hand = top_down(0.0, 0.0, 0.1);
  const double r = 0.03;
  for (int i = 0; i <= 180; ++i)
    for (int j = 0; j < 360; ++j) {
      const double polar = M_PI * i / 180.0, azimuth = 2.0 * M_PI * j / 360.0;
      const Eigen::Vector3d p(centre_x_m + r * std::cos(polar),
                              r * std::sin(polar) * std::cos(azimuth),
                              r * std::sin(polar) * std::sin(azimuth));
      if (p.x() < 0.0 || p.x() > 0.06 || std::abs(p.z()) > 0.01) continue;
      cloud.points_m.push_back((hand.X_FrameHand * p).cast<float>());
      hand.closing_points.push_back(std::int32_t(cloud.size() - 1));
    }
  hand.width_m = 0.06;
  return hand;
}

TEST(ContactDepth, APatchStartsAboveTheWidestPartItMeets) {
  Cloud centred, low;
  // Held at its equator, 3 cm down the 6 cm fingers: each patch (3 mm deep) spans
  // +-sqrt(2 r 3 mm - 9 mm^2) = +-1.3 cm about it.
  EXPECT_NEAR(selectors::contact_start_m(around_ball(0.03, centred), centred, 0.003), 0.017, 1e-3);
  // Its equator 1.5 cm beyond the tips: the widest points the fingers reach are at the tips.
  EXPECT_GT(selectors::contact_start_m(around_ball(0.075, low), low, 0.003), 0.055);
  EXPECT_DOUBLE_EQ(selectors::contact_start_m(top_down(0, 0, 0.1), low, 0.003), 0.0);
  // The later of the two patches decides: a face the -y finger meets along its length, and
  // on the +y side only a strip near the tips.
  Cloud mixed;
  Hand hand = top_down(0.0, 0.0, 0.1);
  const auto add = [&](double x, double y) {
    mixed.points_m.push_back((hand.X_FrameHand * Eigen::Vector3d(x, y, 0.0)).cast<float>());
    hand.closing_points.push_back(std::int32_t(mixed.size() - 1));
  };
  for (double x = 0.005; x <= 0.0551; x += 0.005) add(x, -0.03);
  for (double x = 0.052; x <= 0.0581; x += 0.002) add(x, 0.03);
  EXPECT_NEAR(selectors::contact_start_m(hand, mixed, 0.003), 0.052, 1e-6);
}

TEST_F(ClusterSelectorTest, ABallWidestBeyondTheFingertipsIsNotAGrasp) {
  auto cloud = std::make_shared<Cloud>();
  Hand above = around_ball(0.075, *cloud);
  above.score = 2.0;  // the better score
  const std::size_t first_of_centred = cloud->size();
  Hand centred = around_ball(0.035, *cloud);  // 5 mm clear of the palm
  centred.X_FrameHand.translation().x() = 0.3;
  for (std::size_t i = first_of_centred; i < cloud->size(); ++i) cloud->points_m[i].x() += 0.3f;
  HandSet set = on_table({above, centred});
  set.cloud = cloud;
  const std::string base = "min_cluster_size: 1\nunseen_is_free: true\n";
  const HandSet selection = create(base)->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u) << to_string(selection.hands[0].rejection);
  EXPECT_NEAR(selection.hands[0].position_m().x(), 0.3, 1e-12);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kWidestBeyondTheTips);
  const HandSet unchecked = create(base + "fingertip_margin_m: 0")->select(set, {});
  ASSERT_EQ(grasp_count(unchecked), 2u);
  EXPECT_NEAR(unchecked.hands[0].position_m().x(), 0.0, 1e-12);
  // The only hand: tried as a last resort, unless that is turned off.
  HandSet alone = set;
  alone.hands = {above};
  EXPECT_EQ(grasp_count(create(base)->select(alone, {})), 1u);
  const HandSet strict = create(base + "fingertip_last_resort: false")->select(alone, {});
  EXPECT_EQ(grasp_count(strict), 0u);
  EXPECT_EQ(strict.hands[0].rejection, Rejection::kWidestBeyondTheTips);
}

// The screen (before classification) drops what select() would drop whatever the score, but
// leaves the hands widest beyond the fingertips, which select() tries when nothing else is
// left; only rejections change.
TEST_F(ClusterSelectorTest, TheScreenDropsWhatTheGeometryRulesOutAndLeavesTheTipsToSelection) {
  auto cloud = std::make_shared<Cloud>();
  Hand beyond_tips = around_ball(0.075, *cloud);
  Hand rim = across_band(-0.01, -0.006, *cloud);
  std::vector<Hand> hands = {top_down(0.3, 0, 0.05),
                             top_down(0.4, 0, 0.1, 1.0, 0.08),
                             top_down(0.5, 0, 0.1, 1.0, 0.02),
                             beyond_tips,
                             rim,
                             top_down(0.6, 0, 0.1)};
  hands[1].rejection = Rejection::kNotAntipodal;  // an earlier stage's reason stays
  for (Hand& hand : hands) hand.label = HandLabel::kUnknown, hand.score = 0.0;
  HandSet set = on_table(hands);
  set.cloud = cloud;
  const auto selector = create("min_cluster_size: 1\nunseen_is_free: true");
  const HandSet screened = selector->screen(set, {});
  ASSERT_EQ(screened.hands.size(), hands.size());
  EXPECT_EQ(screened.cloud, set.cloud);
  const std::vector<Rejection> expected = {Rejection::kBelowSupport,      Rejection::kNotAntipodal,
                                           Rejection::kApertureLimit,     Rejection::kNone,
                                           Rejection::kFingersOverAnEdge, Rejection::kNone};
  for (std::size_t i = 0; i < hands.size(); ++i) {
    EXPECT_EQ(screened.hands[i].rejection, expected[i]) << "hand " << i;
    EXPECT_TRUE(screened.hands[i].X_FrameHand.isApprox(hands[i].X_FrameHand)) << "hand " << i;
    EXPECT_EQ(screened.hands[i].label, HandLabel::kUnknown) << "hand " << i;
  }
  // Classified after the screen or not, the selection is the same.
  const auto classify = [](HandSet s) {
    for (Hand& hand : s.hands)
      if (hand.rejection == Rejection::kNone) hand.label = HandLabel::kPositive, hand.score = 1.0;
    return s;
  };
  const HandSet direct = selector->select(classify(set), {});
  const HandSet after_screen = selector->select(classify(screened), {});
  ASSERT_EQ(direct.hands.size(), after_screen.hands.size());
  ASSERT_EQ(grasp_count(direct), 1u);
  EXPECT_EQ(grasp_count(after_screen), 1u);
  for (std::size_t i = 0; i < direct.hands.size(); ++i) {
    EXPECT_EQ(direct.hands[i].rejection, after_screen.hands[i].rejection) << "hand " << i;
    EXPECT_TRUE(direct.hands[i].X_FrameHand.isApprox(after_screen.hands[i].X_FrameHand));
  }
  // With the last hand gone, the ball beyond the tips is the last resort: it was kept for it.
  set.hands.pop_back();
  const HandSet last = selector->select(classify(selector->screen(set, {})), {});
  ASSERT_EQ(grasp_count(last), 1u);
  EXPECT_NEAR(last.hands[0].position_m().x(), 0.0, 1e-12);
}

// Hands on two objects: #0 around x = 0 (scores 5, 4, 3), #1 around x = 0.3 (scores 2, 1).
HandSet on_two_objects() {
  std::vector<Hand> hands;
  for (const auto& [x, score, object] : {std::tuple<double, double, int>{0.0, 5.0, 0},
                                         {0.05, 4.0, 0},
                                         {-0.05, 3.0, 0},
                                         {0.3, 2.0, 1},
                                         {0.35, 1.0, 1}}) {
    Hand hand = top_down(x, 0, 0.1, score);
    hand.object = object;
    hands.push_back(hand);
  }
  HandSet set = on_table(hands);
  for (const int id : {0, 1}) {
    SceneObject object;
    object.id = id;
    object.centroid_m = Eigen::Vector3f(0.3f * float(id), 0.0f, 0.03f);
    set.objects.push_back(object);
  }
  return set;
}

std::vector<int> chosen_objects(const HandSet& selection) {
  std::vector<int> objects;
  for (std::size_t i = 0; i < grasp_count(selection); ++i)
    objects.push_back(selection.hands[i].object);
  return objects;
}

TEST_F(ClusterSelectorTest, GraspsPerObjectAndAnObjectOfInterest) {
  const HandSet set = on_two_objects();
  const std::string base = "min_cluster_size: 1\nunseen_is_free: true\nmax_grasps: 5\n";
  EXPECT_EQ(chosen_objects(create(base)->select(set, {})), (std::vector<int>{0, 0, 0, 1, 1}));
  EXPECT_EQ(chosen_objects(create(base + "grasps_per_object: 1")->select(set, {})),
            (std::vector<int>{0, 1}));
  const HandSet near = create(base + "near_m: [0.28, 0.02, 0.0]")->select(set, {});
  EXPECT_EQ(chosen_objects(near), (std::vector<int>{1, 1}));
  EXPECT_EQ(near.hands[2].rejection, Rejection::kOtherObject);
  EXPECT_EQ(chosen_objects(create(base + "object: 0")->select(set, {})),
            (std::vector<int>{0, 0, 0}));
  // Asked for an object in a scene that was not segmented: nothing is chosen, with the reason.
  HandSet unsegmented = set;
  unsegmented.objects.clear();
  for (Hand& hand : unsegmented.hands) hand.object = -1;
  const HandSet none = create(base + "near_m: [0.3, 0, 0]")->select(unsegmented, {});
  EXPECT_EQ(grasp_count(none), 0u);
  EXPECT_EQ(none.hands[0].rejection, Rejection::kOtherObject);
  EXPECT_EQ(creation_error(base + "object: 1\nnear_m: [0, 0, 0]"),
            "tree.yaml:5:1: give either 'object' or 'near_m', not both");
  EXPECT_EQ(creation_error(base + "object: 1.5"),
            "tree.yaml:4:1: parameter 'object' must be a whole number, got 1.500000");
}

// A hand approaching along +x at height z, its closing direction turned `tilt_deg` from
// the horizontal +y towards +z (about the approach).
Hand from_side(double y, double z, double tilt_deg, double score) {
  Hand hand = top_down(0.0, y, z, score);
  Eigen::Matrix3d r;
  r.col(0) = Eigen::Vector3d::UnitX();
  r.col(1) = Eigen::AngleAxisd(tilt_deg * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
             Eigen::Vector3d::UnitY();
  r.col(2) = r.col(0).cross(r.col(1));
  hand.X_FrameHand.linear() = r;
  return hand;
}

// A plate of points at height z over x in [x0, 0.3], |y| <= 0.3, seen from 1 m above.
Cloud plate_seen_from_above(float x0, float z) {
  Cloud cloud;
  for (float x = x0; x <= 0.3f; x += 0.005f)
    for (float y = -0.3f; y <= 0.3f; y += 0.005f) cloud.points_m.emplace_back(x, y, z);
  cloud.view_origins_m = {Eigen::Vector3f(0.0f, 0.0f, 1.0f)};
  return cloud;
}

TEST(HandClearance, AWayInUnderAnOverhangIsUnseen) {
  const HandGeometry g;
  const Hand hand = from_side(0.0, 0.25, 0.0, 1.0);  // approaching along +x, 5 cm under
  const Cloud over_the_way_in = plate_seen_from_above(-0.3f, 0.3f);
  EXPECT_TRUE(selectors::approach_is_free(hand, g, over_the_way_in, 0.1))
      << "no point lies on the way in";
  EXPECT_FALSE(
      selectors::way_in_is_seen(hand, g, OcclusionMap(over_the_way_in, 0.0025f), 0.1, 0.01f));
  const Cloud over_the_grasp_only = plate_seen_from_above(0.02f, 0.3f);
  EXPECT_TRUE(
      selectors::way_in_is_seen(hand, g, OcclusionMap(over_the_grasp_only, 0.0025f), 0.1, 0.01f));
  EXPECT_TRUE(
      selectors::way_in_is_seen(hand, g, OcclusionMap(over_the_way_in, 0.0025f), 0.1, 0.06f))
      << "5 cm behind the plate is within a 6 cm margin";
}

TEST_F(ClusterSelectorTest, AGraspWhoseWayInIsUnseenIsDroppedUnlessUnseenIsFree) {
  HandSet set = on_table({from_side(0.0, 0.25, 0.0, 1.0)});
  set.cloud = std::make_shared<Cloud>(plate_seen_from_above(-0.3f, 0.3f));
  const HandSet selection = create("min_cluster_size: 1")->select(set, {});
  EXPECT_EQ(grasp_count(selection), 0u);
  EXPECT_EQ(selection.hands.front().rejection, Rejection::kInCollision);
  EXPECT_EQ(grasp_count(create("min_cluster_size: 1\nunseen_is_free: true")->select(set, {})), 1u);
}

TEST(ClosingTilt, AngleOfTheClosingDirectionFromTheSupport) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(selectors::closing_tilt_rad(from_side(0, 0.1, 0.0, 1), up), 0.0, 1e-12);
  EXPECT_NEAR(selectors::closing_tilt_rad(from_side(0, 0.1, 40.0, 1), up), 40 * M_PI / 180, 1e-12);
  EXPECT_NEAR(selectors::closing_tilt_rad(from_side(0, 0.1, -90.0, 1), up), M_PI / 2, 1e-7)
      << "the sign of the closing direction does not matter";
  EXPECT_NEAR(selectors::closing_tilt_rad(turned(top_down(0, 0, 0.1), 70.0), up), 0.0, 1e-12);
  EXPECT_EQ(selectors::tilt_penalty(0.2, 0.25), 0.0);
  EXPECT_NEAR(selectors::tilt_penalty(0.35, 0.25), 0.01, 1e-12);
}

TEST_F(ClusterSelectorTest, ATiltedClosingRanksBelowAFlatterOne) {
  const auto selector = create("min_cluster_size: 1\nmax_grasps: 3");
  const HandSet selection =
      selector->select(on_table({from_side(0.0, 0.1, 45.0, 9.0), from_side(0.2, 0.1, 10.0, 1.0),
                                 from_side(0.4, 0.1, 25.0, 5.0)}),
                       {});
  ASSERT_EQ(grasp_count(selection), 3u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 1.0) << "10 degrees: within the free 15";
  EXPECT_DOUBLE_EQ(selection.hands[1].score, 5.0);
  EXPECT_DOUBLE_EQ(selection.hands[2].score, 9.0) << "45 degrees ranks last";
  const HandSet untilted =
      create("min_cluster_size: 1\nmax_grasps: 3\ntilt_free_deg: 90")
          ->select(on_table({from_side(0.0, 0.1, 45.0, 9.0), from_side(0.2, 0.1, 10.0, 1.0)}), {});
  EXPECT_DOUBLE_EQ(untilted.hands[0].score, 9.0) << "with every tilt free the score decides";
}

// Probabilities of success rank first (scores within score_first_tolerance tie, and the
// tilt decides among them); scores that are only an order come after the tilt.
TEST_F(ClusterSelectorTest, ProbabilitiesOfSuccessRankBeforeTheTilt) {
  const auto selector = create("min_cluster_size: 1\nmax_grasps: 3");
  const auto hands = [] {
    return on_table({from_side(0.0, 0.1, 45.0, 0.9), from_side(0.2, 0.1, 10.0, 0.6),
                     from_side(0.4, 0.1, 25.0, 0.88)});
  };
  const HandSet order = selector->select(hands(), {});
  ASSERT_EQ(grasp_count(order), 3u);
  EXPECT_DOUBLE_EQ(order.hands[0].score, 0.6) << "an order: the flattest closing first";
  HandSet probabilities = hands();
  probabilities.scores = ScoreMeaning::kProbability;
  const HandSet ranked = selector->select(probabilities, {});
  ASSERT_EQ(grasp_count(ranked), 3u);
  EXPECT_DOUBLE_EQ(ranked.hands[0].score, 0.88) << "0.88 ties 0.9 (0.05), and is flatter";
  EXPECT_DOUBLE_EQ(ranked.hands[1].score, 0.9);
  EXPECT_DOUBLE_EQ(ranked.hands[2].score, 0.6) << "0.3 less likely to hold: last";
  const HandSet off = create("min_cluster_size: 1\nmax_grasps: 3\nscore_first_tolerance: 0")
                          ->select(probabilities, {});
  EXPECT_DOUBLE_EQ(off.hands[0].score, 0.6) << "0 keeps the score last";
}

TEST_F(ClusterSelectorTest, AGraspFarFromTheCentreOfMassIsTriedOnlyWhenNoOtherRemains) {
  const auto selector = create("min_cluster_size: 1");
  HandSet set = on_table({top_down(0.0, 0, 0.1, 9.0)});  // held 10 cm from the mass below
  auto cloud = std::make_shared<Cloud>();
  for (int i = 0; i < 10; ++i) cloud->points_m.emplace_back(0.1f, 0.001f * float(i), 0.05f);
  set.cloud = cloud;
  HandSet selection = selector->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u) << "the last resort";
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 9.0);

  set.hands.push_back(top_down(0.1, 0, 0.1, 1.0));  // right above the mass
  selection = selector->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 1.0);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kUnbalanced);
}

TEST_F(ClusterSelectorTest, InASegmentedSceneTheBalanceIsJudgedOnTheGraspsOwnObject) {
  // Object 0 right below hand A, 10 points; object 1, a heavier-looking neighbour 10 cm along
  // x (the axis gravity's lever about a +y closing runs along), 90 points, below hand B.
  auto cloud = std::make_shared<Cloud>();
  SceneObject small{0, {}, Eigen::Vector3f(0.0f, 0.0f, 0.05f), {}, {}, 0.05f};
  SceneObject neighbour{1, {}, Eigen::Vector3f(0.1f, 0.0f, 0.05f), {}, {}, 0.05f};
  for (int i = 0; i < 100; ++i) {
    SceneObject& object = i < 10 ? small : neighbour;
    object.points.push_back(i);
    cloud->points_m.push_back(object.centroid_m +
                              Eigen::Vector3f(0.0f, 0.001f * float(i % 10), 0.0f));
  }
  Hand a = top_down(0.0, 0, 0.1, 9.0), b = top_down(0.1, 0, 0.1, 1.0);
  HandSet set = on_table({a, b});
  set.cloud = cloud;
  const auto selector = create("min_cluster_size: 1");
  // Not segmented: every object point within 15 cm counts, the pile's centroid lies 9 cm
  // from A's grasp, and A is dropped while B remains.
  HandSet selection = selector->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 1.0);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kUnbalanced);
  // Segmented, each hand naming its object: both are balanced, and the score decides.
  set.objects = {small, neighbour};
  set.hands[0].object = 0;
  set.hands[1].object = 1;
  selection = create("min_cluster_size: 1\nmax_grasps: 2")->select(set, {});
  ASSERT_EQ(grasp_count(selection), 2u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 9.0);
}

TEST_F(ClusterSelectorTest, AGraspWhoseWayInIsBlockedIsDroppedWithItsReason) {
  const auto selector = create("min_cluster_size: 1\nmax_grasps: 1");
  HandSet set =
      on_table({top_down(0, 0, 0.1, 2.0), top_down(0.2, 0, 0.1, 1.0), top_down(0.4, 0, 0.1, 0.5)});
  auto cloud = std::make_shared<Cloud>();
  cloud->points_m = {Eigen::Vector3f(0, 0, 0.16)};  // above the best hand's palm
  set.cloud = cloud;
  const HandSet selection = selector->select(set, {});
  ASSERT_EQ(grasp_count(selection), 1u);
  EXPECT_DOUBLE_EQ(selection.hands[0].score, 1.0);
  EXPECT_EQ(selection.hands[1].rejection, Rejection::kInCollision);
  EXPECT_EQ(selection.hands[2].rejection, Rejection::kNotSelected) << "beyond max_grasps";
  EXPECT_EQ(selection.hands[3].merged_into, 1) << "the input hands name their proposal";
}

TEST_F(ClusterSelectorTest, UsesAFixedSupportHeightWhenTheSetHasNone) {
  const auto selector = create("min_cluster_size: 1\nsupport_z_m: 0.02");
  HandSet set = on_table({top_down(0, 0, 0.085)});  // fingertips at 2.5 cm
  set.support.reset();
  EXPECT_EQ(grasp_count(selector->select(set, {})), 1u);
  set.hands[0].X_FrameHand.translation().z() = 0.075;  // fingertips at 1.5 cm
  EXPECT_EQ(selector->select(set, {}).hands.back().rejection, Rejection::kBelowSupport);
}

// A 30 cm bin on the table: a hand whose fingers straddle its +y wall would close on the
// wall; hands inside it, however near the wall, are kept.
TEST_F(ClusterSelectorTest, HandsThatReachIntoABinWallAreDropped) {
  const auto selector = create(
      "min_cluster_size: 1\nbin: {center_m: [0, 0], inner_size_m: [0.3, 0.3], floor_z_m: 0, "
      "wall_height_m: 0.06, wall_thickness_m: 0.01}");
  const HandSet selection =
      selector->select(on_table({top_down(0, 0, 0.1, 3.0), top_down(0.05, 0.155, 0.1, 2.0),
                                 turned(top_down(-0.05, 0.12, 0.1, 1.0), 90)}),
                       {});
  ASSERT_EQ(grasp_count(selection), 2u);
  EXPECT_NEAR(selection.hands[0].position_m().y(), 0.0, 1e-12);
  EXPECT_NEAR(selection.hands[1].position_m().y(), 0.12, 1e-12) << "2 cm from the wall";
  const auto astride = std::find_if(selection.hands.begin(), selection.hands.end(),
                                    [](const Hand& h) { return h.position_m().y() > 0.15; });
  ASSERT_NE(astride, selection.hands.end());
  EXPECT_EQ(astride->rejection, Rejection::kInCollision) << "astride the wall";
  EXPECT_NE(creation_error("bin: {center_m: [0], inner_size_m: [0.3, 0.3]}")
                .find("'center_m' needs two numbers"),
            std::string::npos);
  EXPECT_NE(creation_error("bin: {center_m: [0, 0], inner_size_m: [0.3, 0.3], wall_hight_m: 1}")
                .find("did you mean 'wall_height_m'"),
            std::string::npos);
}

TEST_F(ClusterSelectorTest, RejectsBadParameters) {
  EXPECT_NE(creation_error("min_cluster_sise: 3").find("did you mean 'min_cluster_size'"),
            std::string::npos);
  EXPECT_NE(creation_error("cluster_angle_deg: 200").find("cluster_angle_deg"), std::string::npos);
  EXPECT_NE(creation_error("tilt_free_deg: 95").find("'tilt_free_deg' must be in [0, 90]"),
            std::string::npos);
  EXPECT_NE(creation_error("point_radius_m: 0").find("point_radius_m"), std::string::npos);
  EXPECT_NE(creation_error("max_grasps: 0").find("max_grasps"), std::string::npos);
  EXPECT_NE(creation_error("fingertip_margin_m: -0.01").find("fingertip_margin_m"),
            std::string::npos);
  EXPECT_NE(creation_error("min_finger_cover: 1.5").find("'min_finger_cover' must be in [0, 1]"),
            std::string::npos);
  EXPECT_NE(creation_error("threads: 1.5").find("'threads' must be a whole number"),
            std::string::npos);
  EXPECT_NE(creation_error("threads: 300").find("'threads' must be in [0, 256]"),
            std::string::npos);
  EXPECT_NE(creation_error("reach_search: first_fre")
                .find("'reach_search' must be first_free or exhaustive, got 'first_fre' (did "
                      "you mean 'first_free'?)"),
            std::string::npos);
  EXPECT_NE(creation_error("reach_search: nearest_pregrasp").find("'reach_search' must be"),
            std::string::npos);
  EXPECT_EQ(creation_error("reach_search: exhaustive"), "");
  EXPECT_NE(creation_error("ik_kinematics: one-pass")
                .find("'ik_kinematics' must be one_pass or kdl, got 'one-pass' (did you mean "
                      "'one_pass'?)"),
            std::string::npos);
  EXPECT_EQ(creation_error("ik_kinematics: kdl"), "");
  EXPECT_NE(creation_error("points_octree: per-leaf")
                .find("'points_octree' must be per_leaf or point_by_point, got 'per-leaf' (did "
                      "you mean 'per_leaf'?)"),
            std::string::npos);
  EXPECT_EQ(creation_error("points_octree: point_by_point"), "");
  const HandSet no_cloud;
  EXPECT_THROW(create("{}")->select(no_cloud, {}), Error);
  EXPECT_THROW(create("{}")->screen(no_cloud, {}), Error);
}

// The checks of each hand run on `threads` workers: the same screen and selection for any
// number.
TEST_F(ClusterSelectorTest, TheSameResultForAnyNumberOfThreads) {
  std::vector<Hand> hands;
  for (int i = 0; i < 300; ++i)
    hands.push_back(top_down(0.01 * (i % 30), 0.01 * (i / 30), 0.03 + 0.001 * (i % 50),
                             1.0 + 0.01 * i, 0.015 + 0.0002 * i));
  const HandSet set = on_table(hands);
  const HandSet one = create("threads: 1")->screen(set, {});
  const HandSet two = create("threads: 2")->screen(set, {});
  std::size_t screened = 0;
  for (std::size_t i = 0; i < hands.size(); ++i) {
    EXPECT_EQ(one.hands[i].rejection, two.hands[i].rejection) << i;
    screened += one.hands[i].rejection != Rejection::kNone;
  }
  EXPECT_GT(screened, 0u);
  EXPECT_LT(screened, hands.size());
  const HandSet chosen_one = create("threads: 1")->select(set, {});
  const HandSet chosen_two = create("threads: 2")->select(set, {});
  ASSERT_EQ(chosen_one.hands.size(), chosen_two.hands.size());
  for (std::size_t i = 0; i < chosen_one.hands.size(); ++i) {
    EXPECT_EQ(chosen_one.hands[i].rejection, chosen_two.hands[i].rejection) << i;
    EXPECT_TRUE(chosen_one.hands[i].X_FrameHand.isApprox(chosen_two.hands[i].X_FrameHand)) << i;
  }
}

// With Baxter's model, a grasp the right arm cannot reach is dropped for want of inverse
// kinematics, and the reachable one is kept although the classifier scored it lower.
TEST_F(ClusterSelectorTest, WithARobotTheArmMustReachTheGrasp) {
  const std::string robot = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.yaml";
  // The table 30 cm below the base; a hand over it in front of the right arm, and one
  // 1.5 m out, beyond the arm's reach, scored higher.
  HandSet set = on_table({top_down(0.72, -0.2, -0.17, 1.0), top_down(1.5, -0.2, -0.17, 5.0)});
  set.support->offset = 0.295f;
  auto cloud = std::make_shared<Cloud>();
  cloud->frame = "base";
  set.cloud = cloud;
  const HandSet free_hand = create("min_cluster_size: 1")->select(set, {});
  ASSERT_EQ(grasp_count(free_hand), 2u);
  EXPECT_NEAR(free_hand.hands[0].position_m().x(), 1.5, 1e-9) << "the higher score first";

  SelectionTimes times;
  SelectionContext timed;
  timed.times = &times;
  const HandSet on_arm = create("min_cluster_size: 1\nrobot: " + robot)->select(set, timed);
  EXPECT_GT(times.reach_s, 0.0) << "the reach checks' time is kept when asked for";
  SelectionTimes no_arm;
  timed.times = &no_arm;
  create("min_cluster_size: 1")->select(set, timed);
  EXPECT_EQ(no_arm.reach_s, 0.0);
  ASSERT_EQ(grasp_count(on_arm), 1u);
  EXPECT_NEAR(on_arm.hands[0].position_m().x(), 0.72, 1e-9);
  EXPECT_EQ(on_arm.hands[1].rejection, Rejection::kNoIk);
  EXPECT_NEAR(on_arm.hands[1].position_m().x(), 1.5, 1e-9);

  cloud = std::make_shared<Cloud>();
  cloud->frame = "camera";
  set.cloud = cloud;
  EXPECT_THROW(create("min_cluster_size: 1\nrobot: " + robot)->select(set, {}), Error);
  EXPECT_NE(
      creation_error("robot: /nonexistent.yaml").find("robot: robot file '/nonexistent.yaml'"),
      std::string::npos);
}

// The context's scene, not the hands' cloud, is what the arm must avoid: a wall of points
// where the arm passes (above the grasp, outside any sampler workspace) makes the grasp
// unreachable.
TEST_F(ClusterSelectorTest, TheArmAvoidsTheContextsScene) {
  const std::string robot = std::string(ANTIPODE_TEST_SOURCE_DIR) + "/robots/baxter/baxter.yaml";
  HandSet set = on_table({top_down(0.72, -0.2, -0.17, 1.0)});
  set.support->offset = 0.295f;
  auto empty = std::make_shared<Cloud>();
  empty->frame = "base";
  set.cloud = empty;
  const auto selector = create("min_cluster_size: 1\nrobot: " + robot);
  ASSERT_EQ(grasp_count(selector->select(set, {})), 1u);
  auto ceiling = std::make_shared<Cloud>();  // a sheet of points 15 cm above the palm face
  ceiling->frame = "base";
  for (double x = 0.4; x <= 1.1; x += 0.01)
    for (double y = -0.6; y <= 0.3; y += 0.01)
      ceiling->points_m.emplace_back(float(x), float(y), -0.02f);
  SelectionContext context;
  context.scene = ceiling;
  const HandSet blocked = selector->select(set, context);
  EXPECT_EQ(grasp_count(blocked), 0u);
  EXPECT_EQ(blocked.hands.front().rejection, Rejection::kInCollision);
}

}  // namespace
}  // namespace antipode
