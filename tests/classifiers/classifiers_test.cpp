#include <chrono>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/io/load_cloud.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "synthetic_shapes.hpp"
#include "views.hpp"

namespace antipode {
namespace {

Parameters params(const std::string& yaml) {
  return Parameters(YAML::Load(yaml), "component 'classifier'", "tree.yaml");
}

// A 5 cm can seen from both sides, sampled by the framework's hand search.
HandSet sampled_can(std::size_t samples) {
  const Cloud cloud = testing::seen_from(
      [](const Eigen::Vector3d& c) {
        return testing::cylinder_cloud(c, Eigen::Vector3d::UnitY(), 0.05, 0.15);
      },
      Eigen::Vector3d::Zero(), {{-0.5, 0.0, 0.3}, {0.5, 0.0, 0.3}});
  HandSamplingOptions options;
  options.search.samples = samples;
  return sample_hands(cloud, options, RandomStream(3));
}

class ClassifiersTest : public ::testing::Test {
 protected:
  ClassifiersTest() : host_(std::vector<std::string>{}) {
    for (const char* name : {"passthrough_classifier", "antipodal_classifier"}) {
      host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" + plugin_file_name(name));
    }
  }

  std::shared_ptr<Classifier> create(const std::string& type, const std::string& yaml) {
    return std::dynamic_pointer_cast<Classifier>(host_.create(type, params(yaml)));
  }

  std::string creation_error(const std::string& type, const std::string& yaml) {
    try {
      create(type, yaml);
    } catch (const Error& error) {
      return error.what();
    }
    return "";
  }

  PluginHost host_;
};

TEST_F(ClassifiersTest, BothLoadAsClassifiers) {
  ASSERT_EQ(host_.records().size(), 2u);
  for (const auto& record : host_.records()) {
    EXPECT_EQ(record.state, PluginRecord::State::kLoaded) << record.reason;
  }
  EXPECT_EQ(host_.kind_of("passthrough_classifier"), ComponentKind::kClassifier);
  EXPECT_EQ(host_.kind_of("antipodal_classifier"), ComponentKind::kClassifier);
  EXPECT_NE(create("passthrough_classifier", ""), nullptr);
  EXPECT_NE(create("antipodal_classifier", ""), nullptr);
}

TEST_F(ClassifiersTest, PassthroughLabelsEveryHandPositiveAndKeepsScores) {
  const HandSet sampled = sampled_can(100);
  ASSERT_FALSE(sampled.hands.empty());
  HandSet set = sampled;
  create("passthrough_classifier", "")->classify(set, {});
  ASSERT_EQ(set.hands.size(), sampled.hands.size());
  for (std::size_t i = 0; i < set.hands.size(); ++i) {
    EXPECT_EQ(set.hands[i].label, HandLabel::kPositive);
    EXPECT_EQ(set.hands[i].score, sampled.hands[i].score);
    EXPECT_EQ(set.hands[i].rejection, sampled.hands[i].rejection);
    EXPECT_EQ(set.hands[i].X_FrameHand.matrix(), sampled.hands[i].X_FrameHand.matrix());
  }
}

TEST_F(ClassifiersTest, AntipodalLabelsLikeTheFrameworkCheckForAnyThreadCount) {
  const HandSet sampled = sampled_can(300);
  ASSERT_GT(sampled.hands.size(), 100u);
  const auto counts = count_antipodal_normals(sampled, AntipodalLabellingOptions{});
  std::vector<HandSet> results;
  for (const char* threads : {"1", "2"}) {
    HandSet set = sampled;
    create("antipodal_classifier", std::string("threads: ") + threads)->classify(set, {});
    results.push_back(std::move(set));
  }
  int by_label[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < sampled.hands.size(); ++i) {
    const Hand& hand = results[0].hands[i];
    EXPECT_EQ(hand.label, antipodal_label(counts[i], 6));
    EXPECT_DOUBLE_EQ(hand.score, antipodal_score(counts[i], 6));
    EXPECT_EQ(hand.rejection,
              hand.label == HandLabel::kPositive ? Rejection::kNone : Rejection::kNotAntipodal);
    EXPECT_EQ(hand.label, results[1].hands[i].label);
    EXPECT_EQ(hand.score, results[1].hands[i].score);
    EXPECT_EQ(hand.closing_points, sampled.hands[i].closing_points);
    ++by_label[static_cast<int>(hand.label)];
  }
  EXPECT_GT(by_label[static_cast<int>(HandLabel::kPositive)], 0);
  EXPECT_GT(by_label[static_cast<int>(HandLabel::kNegative)] +
                by_label[static_cast<int>(HandLabel::kIndeterminate)],
            0);
}

TEST_F(ClassifiersTest, AntipodalParametersChangeTheLabels) {
  const HandSet sampled = sampled_can(200);
  auto positives = [&](const std::string& yaml) {
    HandSet set = sampled;
    create("antipodal_classifier", yaml)->classify(set, {});
    return std::count_if(set.hands.begin(), set.hands.end(),
                         [](const Hand& h) { return h.label == HandLabel::kPositive; });
  };
  const auto defaults = positives("");
  EXPECT_EQ(positives("min_points: 6\nmax_angle_deg: 20\nnormal_radius_m: 0.01\n"
                      "min_neighbours: 10\nthreads: 0"),
            defaults);
  EXPECT_LE(positives("min_points: 1000"), 0);
  EXPECT_GE(positives("max_angle_deg: 40"), defaults);
}

TEST_F(ClassifiersTest, AntipodalRejectsASetWithoutCloud) {
  HandSet set;
  set.hands.emplace_back();
  EXPECT_THROW(create("antipodal_classifier", "")->classify(set, {}), Error);
  set.hands.clear();
  EXPECT_NO_THROW(create("antipodal_classifier", "")->classify(set, {}));
}

TEST_F(ClassifiersTest, BadParametersAreLocatedErrors) {
  EXPECT_EQ(creation_error("passthrough_classifier", "threshold: 1"),
            "tree.yaml:1:1: unknown parameter 'threshold' of component 'classifier'");
  EXPECT_EQ(creation_error("antipodal_classifier", "min_point: 6"),
            "tree.yaml:1:1: unknown parameter 'min_point' of component 'classifier' (did you "
            "mean 'min_points'?)");
  EXPECT_EQ(creation_error("antipodal_classifier", "a: 1\nmin_points: 0"),
            "tree.yaml:2:1: parameter 'min_points' must be at least 1, got 0");
  EXPECT_EQ(creation_error("antipodal_classifier", "max_angle_deg: 95"),
            "tree.yaml:1:1: parameter 'max_angle_deg' must be in (0, 90], got 95");
  EXPECT_EQ(creation_error("antipodal_classifier", "max_angle_deg: 0"),
            "tree.yaml:1:1: parameter 'max_angle_deg' must be in (0, 90], got 0");
  EXPECT_EQ(creation_error("antipodal_classifier", "normal_radius_m: -0.01"),
            "tree.yaml:1:1: parameter 'normal_radius_m' must be in (0, 0.1], got -0.01");
  EXPECT_EQ(creation_error("antipodal_classifier", "contact_trim: 0.5"),
            "tree.yaml:1:1: parameter 'contact_trim' must be in [0, 0.45], got 0.5");
  EXPECT_EQ(creation_error("antipodal_classifier", "min_neighbours: 5"),
            "tree.yaml:1:1: parameter 'min_neighbours' must be at least 9, got 5");
  EXPECT_EQ(creation_error("antipodal_classifier", "threads: -1"),
            "tree.yaml:1:1: parameter 'threads' must be at least 0, got -1");
  EXPECT_EQ(creation_error("antipodal_classifier", "min_points: many"),
            "tree.yaml:1:1: parameter 'min_points' of component 'classifier' must be an "
            "integer, got 'many'");
}

// Classifying the hypotheses of a real cloud (skipped without ../shared/data); prints the
// time the antipodal classifier takes.
TEST_F(ClassifiersTest, AntipodalOnTableMugIsFast) {
  const std::string path = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/table_mug.pcd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  const Cloud raw = load_cloud(path);
  const auto classifier = create("antipodal_classifier", "threads: 2");
  for (const bool all_positions : {false, true}) {
    HandSamplingOptions options;
    options.search.samples = 4000;
    options.search.threads = 2;
    options.search.keep_all_positions = all_positions;  // more hands per sample
    HandSet set = sample_hands(raw, options, RandomStream(1));
    ASSERT_GT(set.hands.size(), 1000u);
    const auto start = std::chrono::steady_clock::now();
    classifier->classify(set, {});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int positive = 0, indeterminate = 0;
    for (const Hand& hand : set.hands) {
      positive += hand.label == HandLabel::kPositive;
      indeterminate += hand.label == HandLabel::kIndeterminate;
    }
    std::printf(
        "antipodal_classifier: %zu hands of %zu points in %.1f ms: %d positive, %d "
        "indeterminate\n",
        set.hands.size(), set.cloud->size(), 1e3 * seconds, positive, indeterminate);
    EXPECT_LT(seconds, 2.0);
  }
}

// krylon.pcd is a can seen from all around (no viewpoint): normals point away from its
// centroid, and hands across the can see both of its sides.
TEST_F(ClassifiersTest, AntipodalFindsGraspsOnACanSeenFromAllAround) {
  const std::string path = std::string(ANTIPODE_TEST_DATA_DIR) + "/clouds/krylon.pcd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found; test skipped";
  HandSamplingOptions options;
  options.search.samples = 1000;
  options.search.threads = 2;
  HandSet set = sample_hands(load_cloud(path), options, RandomStream(1));
  ASSERT_TRUE(set.cloud->view_origins_m.empty());
  create("antipodal_classifier", "threads: 2")->classify(set, {});
  int count[4] = {0, 0, 0, 0};
  for (const Hand& hand : set.hands) ++count[static_cast<int>(hand.label)];
  std::printf("krylon: %zu hands: %d positive, %d indeterminate, %d negative\n", set.hands.size(),
              count[1], count[3], count[2]);
  EXPECT_GT(count[1], 0);
}

}  // namespace
}  // namespace antipode
