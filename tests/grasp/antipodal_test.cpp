#include <algorithm>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "synthetic_shapes.hpp"
#include "views.hpp"

namespace antipode {
namespace {

using testing::hand_at;
using testing::seen_from;

// Two sensors on opposite sides of objects standing at the origin, both above them.
const Eigen::Vector3d kLeft(-0.5, 0.0, 0.3);
const Eigen::Vector3d kRight(0.5, 0.0, 0.3);
const Eigen::Vector3d kDown(0.0, 0.0, -1.0);

testing::Shape box(const Eigen::Vector3d& size_m) {
  return [size_m](const Eigen::Vector3d& c) {
    return testing::box_cloud(c, Eigen::Matrix3d::Identity(), size_m);
  };
}

// A cylinder of 5 cm diameter, 15 cm long along y: its side fits in the hand across x.
testing::Shape can() {
  return [](const Eigen::Vector3d& c) {
    return testing::cylinder_cloud(c, Eigen::Vector3d::UnitY(), 0.05, 0.15);
  };
}

struct Labelled {
  AntipodalCount count;
  HandLabel label;
};

Labelled check(const Cloud& cloud, const Hand& hand, const AntipodalParameters& p = {}) {
  const auto normals = estimate_normals(cloud, NormalEstimationOptions{});
  const AntipodalCount count = count_antipodal_normals(hand, cloud.points_m, normals, p);
  return {count, antipodal_label(count, p.min_points)};
}

// A 5 x 5 x 10 cm box (top at z = 5 cm) grasped from above across x, fingers reaching 1 cm
// below its top... down to its middle.
Hand box_hand(const Cloud& cloud, const Eigen::Vector3d& closing = Eigen::Vector3d::UnitX()) {
  return hand_at(cloud, kDown, closing, {0.0, 0.0, 0.06});
}

TEST(AntipodalTest, BoxSeenFromBothSidesIsPositive) {
  const Cloud cloud = seen_from(box({0.05, 0.05, 0.1}), Eigen::Vector3d::Zero(), {kLeft, kRight});
  const Hand hand = box_hand(cloud);
  ASSERT_GT(hand.closing_points.size(), 100u);
  const Labelled result = check(cloud, hand);
  EXPECT_GE(result.count.facing_plus, 100);
  EXPECT_GE(result.count.facing_minus, 100);
  EXPECT_EQ(result.label, HandLabel::kPositive);
}

TEST(AntipodalTest, BoxSeenFromOneSideIsIndeterminateAndTheSignsFollowTheFingers) {
  // Only the -x face is seen: its outward normals point along -x, so with closing = +x they
  // face the finger at -y (the hand's -closing side), which closes along +x onto them.
  const Cloud cloud = seen_from(box({0.05, 0.05, 0.1}), Eigen::Vector3d::Zero(), {kLeft});
  const Labelled result = check(cloud, box_hand(cloud));
  EXPECT_GE(result.count.facing_minus, 100);
  EXPECT_EQ(result.count.facing_plus, 0);
  EXPECT_EQ(result.label, HandLabel::kIndeterminate);
  // The same hand turned half a turn about its approach: the counts swap.
  const Labelled turned = check(cloud, box_hand(cloud, -Eigen::Vector3d::UnitX()));
  EXPECT_EQ(turned.count.facing_plus, result.count.facing_minus);
  EXPECT_EQ(turned.count.facing_minus, result.count.facing_plus);
  EXPECT_EQ(turned.label, HandLabel::kIndeterminate);
}

TEST(AntipodalTest, TopOfAWideBoxIsNegativeFromAnyNumberOfViews) {
  // A 20 cm box: between the fingers there is only its top face, whose normals are
  // perpendicular to the closing direction.
  for (const auto& sensors :
       {std::vector<Eigen::Vector3d>{kLeft}, std::vector<Eigen::Vector3d>{kLeft, kRight}}) {
    const Cloud cloud = seen_from(box({0.2, 0.2, 0.1}), Eigen::Vector3d::Zero(), sensors);
    const Hand hand = hand_at(cloud, kDown, Eigen::Vector3d::UnitX(), {0.0, 0.0, 0.1});
    ASSERT_GT(hand.closing_points.size(), 50u);
    const Labelled result = check(cloud, hand);
    EXPECT_EQ(result.count.facing_plus, 0);
    EXPECT_EQ(result.count.facing_minus, 0);
    EXPECT_EQ(result.label, HandLabel::kNegative) << sensors.size() << " views";
  }
}

TEST(AntipodalTest, CylinderAcrossItsAxis) {
  const Eigen::Vector3d palm(0.0, 0.0, 0.035);
  const Cloud both = seen_from(can(), Eigen::Vector3d::Zero(), {kLeft, kRight});
  EXPECT_EQ(check(both, hand_at(both, kDown, Eigen::Vector3d::UnitX(), palm)).label,
            HandLabel::kPositive);
  const Cloud one = seen_from(can(), Eigen::Vector3d::Zero(), {kRight});
  const Labelled result = check(one, hand_at(one, kDown, Eigen::Vector3d::UnitX(), palm));
  EXPECT_GE(result.count.facing_plus, 6);
  EXPECT_LT(result.count.facing_minus, 6);
  EXPECT_EQ(result.label, HandLabel::kIndeterminate);
}

// A 2 cm wide slab, 3 cm high, under a 1 cm square bar running along x through the whole
// closing region, 5 mm above the slab: closing along x, the slab's faces are aligned, but
// the points nearest each finger are the bar's, whose normals are across x.
testing::Shape bar_over_a_slab() {
  return [](const Eigen::Vector3d& c) {
    Cloud cloud = testing::box_cloud(c + Eigen::Vector3d(0, 0, 0.015), Eigen::Matrix3d::Identity(),
                                     {0.02, 0.05, 0.03});
    testing::append(cloud, testing::box_cloud(c + Eigen::Vector3d(0, 0, 0.04),
                                              Eigen::Matrix3d::Identity(), {0.2, 0.01, 0.01}));
    return cloud;
  };
}

TEST(AntipodalTest, ContactPatchesCountWhatTheFingersMeetFirst) {
  const Cloud cloud = seen_from(bar_over_a_slab(), Eigen::Vector3d::Zero(), {kLeft, kRight});
  const Hand hand = hand_at(cloud, kDown, Eigen::Vector3d::UnitX(), {0.0, 0.0, 0.06});
  AntipodalParameters whole_region;
  whole_region.contact_depth_m = 0.0;  // the paper's Definition 3
  EXPECT_EQ(check(cloud, hand, whole_region).label, HandLabel::kPositive) << "the slab's faces";
  const Labelled patches = check(cloud, hand, AntipodalParameters{});
  EXPECT_EQ(patches.label, HandLabel::kNegative);
  EXPECT_EQ(patches.count.facing_plus + patches.count.facing_minus, 0);
  // The bar's points run on to the closing region's ends: a first contact 5% of the points in
  // from each end still lies on the bar, not on the slab's faces.
  AntipodalParameters trimmed;
  trimmed.contact_trim = 0.05;
  EXPECT_EQ(check(cloud, hand, trimmed).label, HandLabel::kNegative);
  // Without the bar the slab's faces are the first contacts: positive either way.
  const Cloud slab = seen_from(
      [](const Eigen::Vector3d& c) {
        return testing::box_cloud(c + Eigen::Vector3d(0, 0, 0.015), Eigen::Matrix3d::Identity(),
                                  {0.02, 0.05, 0.03});
      },
      Eigen::Vector3d::Zero(), {kLeft, kRight});
  EXPECT_EQ(check(slab, hand_at(slab, kDown, Eigen::Vector3d::UnitX(), {0.0, 0.0, 0.06})).label,
            HandLabel::kPositive);
}

// A lone point a few millimetres off each face (sensor noise at a silhouette) is the farthest
// point towards each finger: a patch measured from it misses the face behind it, and a
// first contact at a quantile (contact_trim) finds the face again.
TEST(AntipodalTest, ATrimmedFirstContactLooksPastLonePoints) {
  Cloud cloud = seen_from(box({0.05, 0.05, 0.1}), Eigen::Vector3d::Zero(), {kLeft, kRight});
  for (const double x : {-0.032, 0.032}) {
    for (const double z : {0.03, 0.035, 0.04}) {
      cloud.points_m.emplace_back(float(x), 0.0f, float(z));
      if (!cloud.view_masks.empty())
        cloud.view_masks.push_back(x < 0.0 ? 1u : 2u);  // its side's view
    }
  }
  const Hand hand = box_hand(cloud);
  ASSERT_GT(hand.closing_points.size(), 200u);
  EXPECT_EQ(check(cloud, hand).label, HandLabel::kNegative) << "patches from the lone points";
  AntipodalParameters trimmed;
  trimmed.contact_trim = 0.05;
  const Labelled result = check(cloud, hand, trimmed);
  EXPECT_EQ(result.label, HandLabel::kPositive);
  EXPECT_GE(std::min(result.count.facing_plus, result.count.facing_minus), 50);
  // Without the lone points the faces are the first contacts either way: the same counts.
  const Cloud clean = seen_from(box({0.05, 0.05, 0.1}), Eigen::Vector3d::Zero(), {kLeft, kRight});
  const Labelled untrimmed_clean = check(clean, box_hand(clean));
  const Labelled trimmed_clean = check(clean, box_hand(clean), trimmed);
  EXPECT_EQ(trimmed_clean.label, HandLabel::kPositive);
  EXPECT_EQ(trimmed_clean.count.facing_plus, untrimmed_clean.count.facing_plus);
  EXPECT_EQ(trimmed_clean.count.facing_minus, untrimmed_clean.count.facing_minus);
}

TEST(AntipodalTest, ContactTrimOutsideItsRangeIsRefused) {
  AntipodalParameters p;
  p.contact_trim = 0.5;
  EXPECT_THROW(p.validate(), Error);
  p.contact_trim = -0.01;
  EXPECT_THROW(p.validate(), Error);
  p.contact_trim = 0.45;
  EXPECT_NO_THROW(p.validate());
}

TEST(AntipodalTest, CylinderAlongItsAxisIsNegative) {
  // Closing along the 15 cm axis: the fingers span only the curved top, whose normals are
  // perpendicular to the axis.
  const Cloud cloud = seen_from(can(), Eigen::Vector3d::Zero(), {kLeft, kRight});
  const Hand hand = hand_at(cloud, kDown, Eigen::Vector3d::UnitY(), {0.0, 0.0, 0.035});
  ASSERT_GT(hand.closing_points.size(), 50u);
  const Labelled result = check(cloud, hand);
  EXPECT_EQ(result.count.facing_plus + result.count.facing_minus, 0);
  EXPECT_EQ(result.label, HandLabel::kNegative);
}

TEST(AntipodalTest, LabelAndScoreFromCounts) {
  EXPECT_EQ(antipodal_label({6, 6}, 6), HandLabel::kPositive);
  EXPECT_EQ(antipodal_label({6, 5}, 6), HandLabel::kIndeterminate);
  EXPECT_EQ(antipodal_label({0, 9}, 6), HandLabel::kIndeterminate);
  EXPECT_EQ(antipodal_label({5, 5}, 6), HandLabel::kNegative);
  EXPECT_DOUBLE_EQ(antipodal_score({12, 3}, 6), 0.5);
  EXPECT_DOUBLE_EQ(antipodal_score({6, 9}, 6), 1.0);
}

TEST(AntipodalTest, AngleThresholdIsInclusiveAndZeroNormalsCountForNeither) {
  Hand hand;  // closing = +y
  hand.closing_points = {0, 1, 2, 3};
  const float c = static_cast<float>(std::cos(19.9 * M_PI / 180.0));
  const float s = std::sqrt(1.0f - c * c);
  const std::vector<Eigen::Vector3f> normals{
      {s, c, 0}, {0, -1, 0}, {0, 0, 0}, {std::sqrt(1.0f - 0.9f * 0.9f), 0.9f, 0}};
  const AntipodalCount count = count_antipodal_normals(hand, normals, 20.0);
  EXPECT_EQ(count.facing_plus, 1);  // 19.9 deg counts, 25.8 deg does not
  EXPECT_EQ(count.facing_minus, 1);
  hand.closing_points.push_back(4);
  EXPECT_THROW(count_antipodal_normals(hand, normals, 20.0), Error);
}

TEST(AntipodalTest, HandSetCountsMatchPerHandChecksForAnyThreadCount) {
  const Cloud cloud = seen_from(can(), Eigen::Vector3d::Zero(), {kLeft, kRight});
  HandSamplingOptions sampling;
  sampling.search.samples = 300;
  const HandSet set = sample_hands(cloud, sampling, RandomStream(4));
  ASSERT_GT(set.hands.size(), 100u);
  AntipodalLabellingOptions options;
  options.normals.threads = 1;
  const auto one = count_antipodal_normals(set, options);
  options.normals.threads = 2;
  const auto two = count_antipodal_normals(set, options);
  const auto normals = estimate_normals(*set.cloud, options.normals);
  ASSERT_EQ(one.size(), set.hands.size());
  int positive = 0;
  for (std::size_t i = 0; i < set.hands.size(); ++i) {
    EXPECT_EQ(one[i].facing_plus, two[i].facing_plus);
    EXPECT_EQ(one[i].facing_minus, two[i].facing_minus);
    const AntipodalCount direct = count_antipodal_normals(set.hands[i], normals, 20.0);
    EXPECT_EQ(direct.facing_plus, one[i].facing_plus);
    EXPECT_EQ(direct.facing_minus, one[i].facing_minus);
    positive += antipodal_label(one[i], 6) == HandLabel::kPositive;
  }
  EXPECT_GT(positive, 0);
}

TEST(AntipodalTest, InvalidInputIsAnError) {
  HandSet set;
  set.hands.emplace_back();
  EXPECT_THROW(count_antipodal_normals(set, AntipodalLabellingOptions{}), Error);  // no cloud
  AntipodalLabellingOptions options;
  options.antipodal.min_points = 0;
  EXPECT_THROW(options.antipodal.validate(), Error);
  options.antipodal = {};
  options.antipodal.max_angle_deg = 95.0;
  EXPECT_THROW(options.antipodal.validate(), Error);
  auto cloud = std::make_shared<Cloud>();
  cloud->points_m = {{0, 0, 1}};
  set.cloud = cloud;
  set.hands[0].closing_points = {1};
  EXPECT_THROW(count_antipodal_normals(set, AntipodalLabellingOptions{}), Error);
}

}  // namespace
}  // namespace antipode
