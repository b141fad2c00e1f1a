// Training examples from labelled hands: closing points in a reference cloud, one descriptor
// per view, class caps, and refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "antipode/core/view_selection.hpp"
#include "antipode/grasp/training_examples.hpp"
#include "support/error_of.hpp"
#include "synthetic_shapes.hpp"
#include "views.hpp"

namespace antipode {
namespace {

using testing::error_of;
using testing::hand_at;
using testing::seen_from;

const Eigen::Vector3d kLeft(-0.5, 0.0, 0.3);
const Eigen::Vector3d kRight(0.5, 0.0, 0.3);
const Eigen::Vector3d kDown(0.0, 0.0, -1.0);

// A 5 x 5 x 10 cm box at the origin seen by both sensors (view 0 left, view 1 right).
std::shared_ptr<Cloud> two_view_box() {
  return std::make_shared<Cloud>(seen_from(
      [](const Eigen::Vector3d& c) {
        return testing::box_cloud(c, Eigen::Matrix3d::Identity(), {0.05, 0.05, 0.1});
      },
      Eigen::Vector3d::Zero(), {kLeft, kRight}));
}

// `count` hands from above across x with the given label, all on the box.
HandSet hands_on(std::shared_ptr<Cloud> cloud, std::size_t count, HandLabel label) {
  HandSet set{cloud, {}, HandGeometry{}, {}};
  for (std::size_t i = 0; i < count; ++i) {
    Hand hand = hand_at(*cloud, kDown, Eigen::Vector3d::UnitX(), {0.0, 0.0, 0.06 + 0.001 * i});
    hand.label = label;
    set.hands.push_back(hand);
  }
  return set;
}

TEST(TrainingExamplesTest, ClosingPointsInAReferenceAreThoseOfTheRegion) {
  const auto both = two_view_box();
  auto left = std::make_shared<Cloud>(*both);
  left->points_m.clear();
  left->view_masks.clear();
  for (std::size_t i = 0; i < both->size(); ++i) {
    if (both->view_masks[i] == 1u) left->points_m.push_back(both->points_m[i]);
  }
  left->view_masks.assign(left->points_m.size(), 1u);
  const HandSet one_view = hands_on(left, 1, HandLabel::kUnknown);
  const HandSet rebased = with_closing_points_in(one_view, both, 2);
  ASSERT_EQ(rebased.hands.size(), 1u);
  EXPECT_EQ(rebased.cloud, both);
  // The reference sees both sides: more points, and the same as placing the hand there.
  const Hand direct = hand_at(*both, kDown, Eigen::Vector3d::UnitX(), {0.0, 0.0, 0.06});
  EXPECT_GT(rebased.hands[0].closing_points.size(), one_view.hands[0].closing_points.size());
  EXPECT_EQ(rebased.hands[0].closing_points, direct.closing_points);
  EXPECT_EQ(rebased.hands[0].X_FrameHand.matrix(), one_view.hands[0].X_FrameHand.matrix());
}

TEST(TrainingExamplesTest, EveryLabelledHandGivesOneDescriptorPerView) {
  HandSet set = hands_on(two_view_box(), 3, HandLabel::kPositive);
  set.hands[1].label = HandLabel::kNegative;
  set.hands.push_back(set.hands[0]);
  set.hands.back().label = HandLabel::kIndeterminate;
  TrainingSet out;
  const ExampleCounts counts = add_examples(set, ExampleOptions{}, 7, RandomStream(1), out);
  EXPECT_EQ(counts.positive_hands, 2u);
  EXPECT_EQ(counts.negative_hands, 1u);
  EXPECT_EQ(counts.skipped_hands, 1u);
  ASSERT_EQ(out.size(), 9u);  // C1, C2 and C12 of three hands
  EXPECT_EQ(out.positives(), 6u);
  EXPECT_EQ(out.dimension, out.descriptor.descriptor_size());
  EXPECT_TRUE(std::all_of(out.sources.begin(), out.sources.end(), [](int s) { return s == 7; }));
  // A hand's three descriptors share a group; the groups of different hands differ.
  EXPECT_EQ(out.groups[0], out.groups[2]);
  EXPECT_NE(out.groups[0], out.groups[3]);
  // C1 and C2 see different sides of the box: different images; C12 is neither.
  const auto row = [&](std::size_t i) {
    return std::vector<float>(out.row(i), out.row(i) + out.dimension);
  };
  EXPECT_NE(row(0), row(1));
  EXPECT_NE(row(2), row(0));
  EXPECT_NE(row(2), row(1));
}

TEST(TrainingExamplesTest, ASingleViewDescriptorIsComputedOnThatViewsPointsAlone) {
  // Hands on the box's top edge, where the views' neighbourhoods differ: normals fitted on
  // the two-view cloud are not those a one-sensor robot would get.
  const auto both = two_view_box();
  HandSet set{both, {}, HandGeometry{}, {}};
  for (const double y : {-0.02, 0.0, 0.02}) {
    Hand hand = hand_at(*both, kDown, Eigen::Vector3d::UnitX(), {0.0, y, 0.06});
    hand.label = HandLabel::kPositive;
    set.hands.push_back(hand);
  }
  ExampleOptions options;
  options.single_views = {1};
  options.all_views = false;
  TrainingSet out;
  add_examples(set, options, 0, RandomStream(1), out);
  ASSERT_EQ(out.size(), set.hands.size());

  std::vector<std::int32_t> new_index;
  HandSet right{
      std::make_shared<Cloud>(points_of_views(*both, {1}, &new_index)), {}, set.geometry, {}};
  HandSet right_on_both{both, {}, set.geometry, {}};  // same points, two-view neighbourhoods
  for (const Hand& hand : set.hands) {
    Hand seen = hand, seen_in_both = hand;
    seen.closing_points.clear();
    seen_in_both.closing_points.clear();
    for (const std::int32_t i : hand.closing_points) {
      if (new_index[static_cast<std::size_t>(i)] < 0) continue;
      seen.closing_points.push_back(new_index[static_cast<std::size_t>(i)]);
      seen_in_both.closing_points.push_back(i);
    }
    right.hands.push_back(seen);
    right_on_both.hands.push_back(seen_in_both);
  }
  const auto expected = hand_descriptors(right, set.geometry, options.descriptor, 1);
  const auto two_view_normals =
      hand_descriptors(right_on_both, set.geometry, options.descriptor, 1);
  bool differs = false;
  for (std::size_t h = 0; h < expected.size(); ++h) {
    EXPECT_EQ(std::vector<float>(out.row(h), out.row(h) + out.dimension), expected[h]) << h;
    differs = differs || expected[h] != two_view_normals[h];
  }
  EXPECT_TRUE(differs) << "the test's hands do not tell the two clouds apart";
}

TEST(TrainingExamplesTest, AViewWithTooFewPointsGivesNoDescriptor) {
  const HandSet set = hands_on(two_view_box(), 1, HandLabel::kPositive);
  ExampleOptions options;
  options.min_points = set.hands[0].closing_points.size();  // only C12 has them all
  TrainingSet out;
  add_examples(set, options, 0, RandomStream(1), out);
  EXPECT_EQ(out.size(), 1u);
}

TEST(TrainingExamplesTest, ClassCapsDrawTheSameHandsForTheSameStream) {
  const HandSet set = hands_on(two_view_box(), 12, HandLabel::kPositive);
  ExampleOptions options;
  options.max_hands_per_label = 5;
  options.single_views = {};
  TrainingSet a, b, c;
  const ExampleCounts counts = add_examples(set, options, 0, RandomStream(3), a);
  add_examples(set, options, 0, RandomStream(3), b);
  add_examples(set, options, 0, RandomStream(4), c);
  EXPECT_EQ(counts.positive_hands, 5u);
  EXPECT_EQ(counts.dropped_hands, 7u);
  EXPECT_EQ(a.size(), 5u);
  EXPECT_EQ(a.features, b.features);
  EXPECT_NE(a.features, c.features);
}

TEST(TrainingExamplesTest, SameExamplesForAnyThreadCount) {
  const HandSet set = hands_on(two_view_box(), 40, HandLabel::kNegative);
  ExampleOptions one, two;
  one.threads = 1;
  two.threads = 2;
  TrainingSet a, b;
  add_examples(set, one, 0, RandomStream(1), a);
  add_examples(set, two, 0, RandomStream(1), b);
  EXPECT_EQ(a.features, b.features);
  EXPECT_EQ(a.groups, b.groups);
}

TEST(TrainingExamplesTest, RefusesMissingViewsAndAnotherHand) {
  const HandSet set = hands_on(two_view_box(), 1, HandLabel::kPositive);
  ExampleOptions options;
  options.single_views = {0, 2};
  TrainingSet out;
  EXPECT_EQ(error_of([&] { add_examples(set, options, 0, RandomStream(1), out); }),
            "training examples: view 2 is not in the cloud (it has 2 view(s))");
  add_examples(set, ExampleOptions{}, 0, RandomStream(1), out);
  HandSet wider = set;
  wider.geometry.max_aperture_m = 0.08;
  wider.geometry.outer_diameter_m = 0.1;
  EXPECT_NE(error_of([&] {
              add_examples(wider, ExampleOptions{}, 0, RandomStream(1), out);
            }).find("differ from the training set's"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode
