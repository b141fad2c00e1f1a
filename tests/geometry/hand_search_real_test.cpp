// The hand search on the shared real clouds (skipped when ../shared/data is absent).
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "antipode/geometry/hand_search.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/io/load_cloud.hpp"
#include "hand_checks.hpp"

namespace antipode {
namespace {

std::string shared_cloud(const std::string& name) {
  return std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/" + name;
}

#define SKIP_WITHOUT(path)                                                   \
  if (!std::filesystem::exists(path)) {                                      \
    GTEST_SKIP() << "shared cloud " << (path) << " not found; test skipped"; \
  }

TEST(HandSearchRealTest, HandsOnTheKrylonCan) {
  const std::string path = shared_cloud("krylon.pcd");
  SKIP_WITHOUT(path);
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  HandSearchParameters parameters;
  parameters.samples = 1000;
  const HandSearchResult result = search_hands(cloud, parameters, RandomStream(1));
  EXPECT_GE(result.hands.size(), 100u);
  testing::expect_valid_hands(cloud, result, parameters);
}

TEST(HandSearchRealTest, ObjectCentredCloudIsSeenFromAllAround) {
  // krylon.pcd has no VIEWPOINT, so its view origin is the frame's origin - the centre of
  // the can. No sensor saw the can from there: sample_hands searches it as seen from all
  // around, so every hand approaches its sample from outside the can.
  const std::string path = shared_cloud("krylon.pcd");
  SKIP_WITHOUT(path);
  HandSamplingOptions options;
  options.search.samples = 1000;
  options.search.threads = 2;
  HandSearchStats stats;
  const HandSet set = sample_hands(load_cloud(path), options, RandomStream(1), &stats);
  EXPECT_TRUE(set.cloud->view_origins_m.empty());
  ASSERT_GE(set.hands.size(), 100u);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : set.cloud->points_m) centroid += p.cast<double>();
  centroid /= static_cast<double>(set.cloud->size());
  for (const Hand& hand : set.hands) {
    const Eigen::Vector3d sample = set.cloud->points_m[hand.sample_index].cast<double>();
    EXPECT_LE(hand.approach().dot(sample - centroid), 1e-6)
        << "hand from inside the can at " << hand.position_m().transpose();
  }
}

// The table of table_mug.pcd: the plane through the points outside the box around the mug
// (the scene is the table and the mug).
struct Plane {
  Eigen::Vector3f normal;  // towards the sensor
  float offset;            // normal . p + offset = height above the table
  float height(const Eigen::Vector3f& p) const { return normal.dot(p) + offset; }
};

const AxisBox kAroundMug{Eigen::Vector3f(-0.02f, -0.02f, 0.68f),
                         Eigen::Vector3f(0.16f, 0.14f, 0.84f)};

Plane table_plane(const Cloud& cloud) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> table;
  for (const auto& p : cloud.points_m) {
    if (!kAroundMug.contains(p)) table.push_back(p.cast<double>()), mean += table.back();
  }
  mean /= static_cast<double>(table.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : table) covariance += (p - mean) * (p - mean).transpose();
  Eigen::Vector3d normal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
  if (normal.dot(-mean) < 0) normal = -normal;
  return {normal.cast<float>(), static_cast<float>(-normal.dot(mean))};
}

TEST(HandSearchRealTest, HandsOnTheMugAboveTheTable) {
  const std::string path = shared_cloud("table_mug.pcd");
  SKIP_WITHOUT(path);
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  const Plane table = table_plane(cloud);
  HandSearchParameters parameters;  // defaults: 4000 samples over the whole scene
  const HandSearchResult result = search_hands(cloud, parameters, RandomStream(1));
  testing::expect_valid_hands(cloud, result, parameters);
  std::size_t on_mug = 0;
  for (const Hand& hand : result.hands) {
    std::size_t above = 0;
    for (const std::int32_t i : hand.closing_points) {
      if (table.height(cloud.points_m[static_cast<std::size_t>(i)]) > 0.015f) ++above;
    }
    if (2 * above <= hand.closing_points.size()) continue;
    ++on_mug;
    const Eigen::Vector3f& sample = cloud.points_m[static_cast<std::size_t>(hand.sample_index)];
    EXPECT_TRUE(kAroundMug.contains(sample))
        << "hand above the table away from the mug, sampled at " << sample.transpose();
  }
  EXPECT_GE(on_mug, 100u) << "of " << result.hands.size() << " hands";
}

TEST(HandSearchRealTest, BestHandsAreOnTheMugWithoutASampleRegion) {
  // The default search over the whole cropped scene: the table is the support plane, so the
  // hands by the table's cut border (which looks like a plate's edge) are gone and the
  // best-scored hands are on the mug.
  const std::string path = shared_cloud("table_mug.pcd");
  SKIP_WITHOUT(path);
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  HandSearchParameters parameters;
  parameters.threads = 2;
  const HandSearchResult result = search_hands(cloud, parameters, RandomStream(1));
  ASSERT_TRUE(result.support_plane.has_value());
  std::vector<const Hand*> best;
  for (const Hand& hand : result.hands) best.push_back(&hand);
  ASSERT_GE(best.size(), 100u);
  std::stable_sort(best.begin(), best.end(),
                   [](const Hand* a, const Hand* b) { return a->score > b->score; });
  const AxisBox mug{Eigen::Vector3f(-0.05f, -0.05f, 0.65f), Eigen::Vector3f(0.2f, 0.15f, 0.85f)};
  for (std::size_t k = 0; k < 30; ++k) {
    EXPECT_TRUE(mug.contains(best[k]->position_m().cast<float>()))
        << "hand " << k << " of the 30 best at " << best[k]->position_m().transpose();
  }
  std::size_t on_mug = 0;
  for (const Hand* hand : best) on_mug += mug.contains(hand->position_m().cast<float>());
  EXPECT_GE(on_mug, best.size() * 95 / 100);
}

TEST(HandSearchRealTest, SampleRegionAroundTheMugKeepsHandsOnIt) {
  const std::string path = shared_cloud("table_mug.pcd");
  SKIP_WITHOUT(path);
  const Cloud cloud = preprocess(load_cloud(path), PreprocessOptions{});
  const Plane table = table_plane(cloud);
  HandSearchParameters parameters;
  parameters.samples = 1000;
  parameters.sample_region = kAroundMug;
  const HandSearchResult result = search_hands(cloud, parameters, RandomStream(2));
  ASSERT_GE(result.hands.size(), 50u);
  std::size_t above = 0;
  for (const Hand& hand : result.hands) {
    if (table.height(cloud.points_m[static_cast<std::size_t>(hand.sample_index)]) > 0.01f) ++above;
  }
  EXPECT_GE(above, result.hands.size() * 9 / 10);
}

}  // namespace
}  // namespace antipode
