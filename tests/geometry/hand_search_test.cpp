// The hand search on synthetic single-view clouds (a sensor at the origin, objects 60 cm
// away along z).
#include "antipode/geometry/hand_search.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "hand_checks.hpp"
#include "synthetic_shapes.hpp"

namespace antipode {
namespace {

using testing::ShapeOptions;

const Eigen::Vector3d kCentre(0.02, -0.01, 0.6);
const Eigen::Vector3d kAxis = Eigen::Vector3d(0.2, 1.0, 0.1).normalized();

HandSearchParameters small_search() {
  HandSearchParameters parameters;
  parameters.samples = 400;
  parameters.threads = 2;
  return parameters;
}

struct Search {
  Cloud cloud;
  HandSearchResult result;
};

Search search(const Cloud& raw, const HandSearchParameters& parameters, std::uint64_t seed = 7) {
  Search s;
  s.cloud = preprocess(raw, PreprocessOptions{});
  s.result = search_hands(s.cloud, parameters, RandomStream(seed));
  testing::expect_valid_hands(s.cloud, s.result, parameters);
  return s;
}

ShapeOptions with_noise(double noise) {
  ShapeOptions options;
  options.noise_m = noise;
  return options;
}

class NoiseTest : public ::testing::TestWithParam<double> {};

TEST_P(NoiseTest, NarrowCylindersGiveHandsClosingAcrossThem) {
  for (const double diameter : {0.04, 0.06}) {
    SCOPED_TRACE(diameter);
    const Search s =
        search(testing::cylinder_cloud(kCentre, kAxis, diameter, 0.15, with_noise(GetParam())),
               small_search());
    ASSERT_GE(s.result.hands.size(), 40u);
    std::size_t across = 0;
    for (const Hand& hand : s.result.hands) {
      if (std::abs(hand.closing().dot(kAxis)) < 0.2 && std::abs(hand.axis().dot(kAxis)) > 0.95) {
        ++across;
      }
    }
    EXPECT_GE(across, s.result.hands.size() * 8 / 10);
  }
}

TEST_P(NoiseTest, BoxAndSphereGiveHands) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()).toRotationMatrix();
  const Search box = search(testing::box_cloud(kCentre, rotation, Eigen::Vector3d(0.05, 0.12, 0.06),
                                               with_noise(GetParam())),
                            small_search());
  EXPECT_GE(box.result.hands.size(), 40u);
  const Search sphere =
      search(testing::sphere_cloud(kCentre, 0.06, with_noise(GetParam())), small_search());
  EXPECT_GE(sphere.result.hands.size(), 40u);
}

TEST_P(NoiseTest, WideCylinderGivesNoHand) {
  const Search s = search(
      testing::cylinder_cloud(kCentre, kAxis, 0.10, 0.15, with_noise(GetParam())), small_search());
  EXPECT_EQ(s.result.hands.size(), 0u);
  EXPECT_GT(s.result.stats.too_shallow + s.result.stats.hidden, 0u);
}

TEST_P(NoiseTest, InsideOfAPlaneGivesNoHand) {
  const Eigen::Vector3d normal = Eigen::Vector3d(0.0, -0.3, -1.0).normalized();
  HandSearchParameters parameters = small_search();
  parameters.sample_region =
      AxisBox{Eigen::Vector3f(-0.15f, -0.15f, 0.0f), Eigen::Vector3f(0.15f, 0.15f, 2.0f)};
  const Search s =
      search(testing::plane_cloud(kCentre, normal, 0.6, with_noise(GetParam())), parameters);
  EXPECT_EQ(s.result.hands.size(), 0u);
  EXPECT_EQ(s.result.stats.samples, 400u);
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutNoise, NoiseTest, ::testing::Values(0.0, 0.001));

// A table seen from above at 45 degrees (its top through kOnTable, normal kTableUp), a
// square of `table_side_m`, with a 5 cm can 12 cm tall standing on it.
const Eigen::Vector3d kTableUp = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();
const Eigen::Vector3d kOnTable(0.0, 0.0, 0.7);

Cloud can_on_table(double table_side_m) {
  Cloud cloud = testing::plane_cloud(kOnTable, kTableUp, table_side_m);
  testing::append(cloud, testing::cylinder_cloud(kOnTable + 0.06 * kTableUp, kTableUp, 0.05, 0.12));
  return cloud;
}

TEST(HandSearchTest, CylinderStandingOnATableGivesHandsOnTheCylinderOnly) {
  // A table seen from above at 45 degrees, a 5 cm can standing on it.
  const Eigen::Vector3d up = kTableUp, on_table = kOnTable;
  const Cloud cloud = can_on_table(0.5);
  HandSearchParameters parameters = small_search();
  parameters.samples = 1000;
  // Samples away from the table's border: a plate's edge can be grasped.
  parameters.sample_region =
      AxisBox{Eigen::Vector3f(-0.1f, -0.1f, 0.5f), Eigen::Vector3f(0.1f, 0.1f, 0.9f)};
  const Search s = search(cloud, parameters);
  ASSERT_GE(s.result.hands.size(), 20u);
  for (const Hand& hand : s.result.hands) {
    const Eigen::Vector3d sample = s.cloud.points_m[hand.sample_index].cast<double>();
    EXPECT_GT((sample - on_table).dot(up), 0.005)
        << "a hand on the table: sample " << sample.transpose() << " approach.up "
        << hand.approach().dot(up) << " closing.up " << hand.closing().dot(up) << " width "
        << hand.width_m << " bite " << hand.score << " from the can's axis "
        << ((sample - on_table) - (sample - on_table).dot(up) * up).norm();
  }
}

// The lowest point of the hand body (fingers and palm) along `up`, relative to `on_table`.
double lowest_point(const Hand& hand, const HandSearchParameters& parameters,
                    const Eigen::Vector3d& up, const Eigen::Vector3d& on_table) {
  const HandBody body = make_hand_body(parameters.hand);
  double lowest = std::numeric_limits<double>::infinity();
  for (const HandBox* box : {&body.finger_minus_y, &body.finger_plus_y, &body.palm}) {
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d c((corner & 1) ? box->max_m.x() : box->min_m.x(),
                              (corner & 2) ? box->max_m.y() : box->min_m.y(),
                              (corner & 4) ? box->max_m.z() : box->min_m.z());
      lowest = std::min(lowest, (hand.X_FrameHand * c - on_table).dot(up));
    }
  }
  return lowest;
}

TEST(HandSearchTest, NoHandReachesIntoTheSupportPlane) {
  // The same scene sampled everywhere: the table is found as the support, so no sample is
  // drawn from it, and no hand reaches below it - not even past its cut border, where there
  // are no points to collide with.
  const Eigen::Vector3d up = kTableUp, on_table = kOnTable;
  const Cloud cloud = can_on_table(0.3);
  HandSearchParameters parameters = small_search();
  parameters.samples = 1000;
  const Search s = search(cloud, parameters);
  ASSERT_TRUE(s.result.support_plane.has_value());
  EXPECT_GT(s.result.support_plane->normal.cast<double>().dot(up), 0.999);
  EXPECT_GT(s.result.stats.on_support, s.cloud.size() / 2);
  ASSERT_GE(s.result.hands.size(), 20u);
  // The fitted plane lies within a millimetre of the table's.
  const double floor = parameters.support_clearance_m - 1e-3;
  for (const Hand& hand : s.result.hands) {
    const Eigen::Vector3d sample = s.cloud.points_m[hand.sample_index].cast<double>();
    EXPECT_GT((sample - on_table).dot(up), parameters.support.distance_m - 1e-3);
    EXPECT_GE(lowest_point(hand, parameters, up, on_table), floor)
        << "hand at " << hand.position_m().transpose() << " comes too near the table";
  }
  const double margin = parameters.support.distance_m;
  // Without the support, hands grip the table's border and reach below it.
  parameters.support_plane = SupportPlaneMode::kNone;
  const Search none = search(cloud, parameters);
  EXPECT_FALSE(none.result.support_plane.has_value());
  std::size_t below = 0;
  for (const Hand& hand : none.result.hands) {
    below += lowest_point(hand, parameters, up, on_table) < -margin;
  }
  EXPECT_GT(below, 0u);
}

TEST(HandSearchTest, TheSupportStopsTheHandAboveALowObject) {
  // A box 2.5 cm high and 5 cm wide lying on the table: from above, the fingers reach the
  // table's clearance before the palm meets the box, so the support stops the push, and the
  // hand holds the box over less than min_bite_m.
  const Eigen::Vector3d up = Eigen::Vector3d(0.0, -1.0, -1.0).normalized();
  const Eigen::Vector3d on_table(0.0, 0.0, 0.7);
  Cloud cloud = testing::plane_cloud(on_table, up, 0.3);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = up.cross(x);
  Eigen::Matrix3d rotation;
  rotation << x, y, up;
  testing::append(cloud, testing::box_cloud(on_table + 0.0125 * up, rotation,
                                            Eigen::Vector3d(0.05, 0.12, 0.025)));
  HandSearchParameters parameters = small_search();
  parameters.samples = 1000;
  const Search s = search(cloud, parameters);
  std::size_t from_above = 0;
  for (const Hand& hand : s.result.hands) {
    if (hand.approach().dot(-up) < 0.95) continue;
    ++from_above;
    const double lowest = lowest_point(hand, parameters, up, on_table);
    EXPECT_GE(lowest, parameters.support_clearance_m - 1e-3);
    EXPECT_LT(hand.score, parameters.min_bite_m);
    EXPECT_GE(hand.score, parameters.min_bite_at_support_m - 1e-6);
  }
  EXPECT_GT(from_above, 0u);
  // Asking the full bite of such hands leaves none from above.
  parameters.min_bite_at_support_m = parameters.min_bite_m;
  const Search strict = search(cloud, parameters);
  for (const Hand& hand : strict.result.hands) EXPECT_LT(hand.approach().dot(-up), 0.95);
}

// Hands that come down at about `tilt_deg` from level and close level (within 6 degrees).
std::size_t tilted_level_closing(const Search& s, const Eigen::Vector3d& up, double tilt_deg) {
  std::size_t count = 0;
  for (const Hand& hand : s.result.hands) {
    const double down = -std::asin(hand.approach().dot(up)) * 180.0 / M_PI;
    count += std::abs(down - tilt_deg) < 6.0 && std::abs(hand.closing().dot(up)) < 0.1;
  }
  return count;
}

TEST(HandSearchTest, TiltedFramesComeDownOnAStandingCanAndCloseLevel) {
  // The can's curvature axis is vertical, so the paper's hands approach it level only; a
  // tilted frame turns the approach down by the tilt and keeps the fingers closing level.
  const Eigen::Vector3d up = kTableUp, on_table = kOnTable;
  const Cloud cloud = can_on_table(0.3);
  HandSearchParameters parameters = small_search();
  parameters.samples = 1000;
  const Search level = search(cloud, parameters);
  EXPECT_EQ(level.result.stats.tilted_hands, 0u);
  EXPECT_EQ(tilted_level_closing(level, up, 30.0), 0u);

  parameters.approach_tilts_deg = {30.0};
  const Search tilted = search(cloud, parameters);
  EXPECT_GE(tilted_level_closing(tilted, up, 30.0), 20u);
  EXPECT_GT(tilted.result.stats.tilted_hands, 0u);
  EXPECT_EQ(tilted.result.stats.hands, tilted.result.hands.size());
  EXPECT_EQ(tilted.result.hands.size(),
            level.result.hands.size() + tilted.result.stats.tilted_hands);
  for (const Hand& hand : tilted.result.hands) {
    EXPECT_GE(lowest_point(hand, parameters, up, on_table), parameters.support_clearance_m - 1e-3);
  }

  // Without a support there is no "down": no tilted hands.
  parameters.support_plane = SupportPlaneMode::kNone;
  EXPECT_EQ(search(cloud, parameters).result.stats.tilted_hands, 0u);
}

TEST(HandSearchTest, ResultDoesNotDependOnThreadCount) {
  const Cloud cloud = preprocess(
      testing::cylinder_cloud(kCentre, kAxis, 0.05, 0.15, with_noise(0.001)), PreprocessOptions{});
  HandSearchParameters parameters = small_search();
  parameters.threads = 1;
  const HandSearchResult one = search_hands(cloud, parameters, RandomStream(11));
  parameters.threads = 2;
  const HandSearchResult two = search_hands(cloud, parameters, RandomStream(11));
  ASSERT_GT(one.hands.size(), 0u);
  EXPECT_TRUE(testing::same_hands(one, two));
  const HandSearchResult other_seed = search_hands(cloud, parameters, RandomStream(12));
  EXPECT_NE(one.sample_points, other_seed.sample_points);
}

TEST(HandSearchTest, SamplesAreDistinctAndCappedByTheCloud) {
  const Cloud cloud = preprocess(testing::sphere_cloud(kCentre, 0.06), PreprocessOptions{});
  HandSearchParameters parameters = small_search();
  parameters.samples = 100;
  HandSearchResult result = search_hands(cloud, parameters, RandomStream(1));
  std::vector<std::int32_t> sorted = result.sample_points;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end());
  EXPECT_EQ(sorted.size(), 100u);
  parameters.samples = cloud.size() + 10;
  result = search_hands(cloud, parameters, RandomStream(1));
  EXPECT_EQ(result.sample_points.size(), cloud.size());
}

TEST(HandSearchTest, KeepingAllPositionsGivesMoreHands) {
  const Cloud cloud =
      preprocess(testing::cylinder_cloud(kCentre, kAxis, 0.04, 0.15), PreprocessOptions{});
  HandSearchParameters parameters = small_search();
  const std::size_t one_per_orientation =
      search_hands(cloud, parameters, RandomStream(3)).hands.size();
  parameters.keep_all_positions = true;
  const HandSearchResult all = search_hands(cloud, parameters, RandomStream(3));
  testing::expect_valid_hands(cloud, all, parameters);
  EXPECT_GT(all.hands.size(), 2 * one_per_orientation);
}

TEST(HandSearchTest, InvalidInputIsAnError) {
  const Cloud cloud = preprocess(testing::sphere_cloud(kCentre, 0.06), PreprocessOptions{});
  HandSearchParameters parameters;
  parameters.orientations = 0;
  EXPECT_THROW(search_hands(cloud, parameters, RandomStream(1)), Error);
  parameters = HandSearchParameters{};
  parameters.hand.min_aperture_m = 0.1;
  EXPECT_THROW(search_hands(cloud, parameters, RandomStream(1)), Error);
  EXPECT_THROW(search_hands(Cloud{}, HandSearchParameters{}, RandomStream(1)), Error);
  parameters = HandSearchParameters{};
  parameters.approach_tilts_deg = {30.0, 90.0};
  try {
    search_hands(cloud, parameters, RandomStream(1));
    ADD_FAILURE() << "a 90-degree tilt was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "hand search: approach_tilts_deg must be in (0, 80], got 90");
  }
}

// A sample region without points (a box whose objects have all been picked) gives no hands:
// nothing to grasp there, which is not an error.
TEST(HandSearchTest, AnEmptySampleRegionGivesNoHands) {
  const Cloud cloud = preprocess(testing::sphere_cloud(kCentre, 0.06), PreprocessOptions{});
  HandSearchParameters parameters;
  parameters.sample_region = AxisBox{Eigen::Vector3f(5, 5, 5), Eigen::Vector3f(6, 6, 6)};
  const auto result = search_hands(cloud, parameters, RandomStream(1));
  EXPECT_TRUE(result.hands.empty());
  EXPECT_EQ(result.stats.samples, 0u);
}

}  // namespace
}  // namespace antipode
