#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/svm_training.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/plugin/plugin_host.hpp"
#include "support/error_of.hpp"
#include "support/toy_hands.hpp"

namespace antipode {
namespace {

namespace fs = std::filesystem;
using testing::error_of;

// `count` toy hands, alternately positive and negative, sharing one cloud.
struct ToyHands {
  HandSet set;
  std::vector<bool> positive;
};

ToyHands toy_hands(std::size_t count, std::uint64_t seed) {
  RandomStream random(seed);
  ToyHands toy;
  for (std::size_t i = 0; i < count; ++i) toy.positive.push_back(i % 2 == 0);
  toy.set = testing::toy_hand_set(toy.positive, random);
  return toy;
}

std::string model_dir() { return (fs::temp_directory_path() / "antipode_hog_svm_test").string(); }

// A model trained on toy hands, saved once in model_dir()/models/toy.model.
const SvmModel& toy_model() {
  static const SvmModel model = [] {
    const ToyHands toy = toy_hands(200, 1);
    const auto descriptors = hand_descriptors(toy.set, HandGeometry{}, {}, 2);
    TrainingSet set;
    for (std::size_t i = 0; i < descriptors.size(); ++i) {
      set.add(descriptors[i], toy.positive[i], static_cast<std::int32_t>(i), 0);
    }
    SvmTrainingOptions options;
    options.pca_components = 24;
    options.c_values = {10.0};
    options.folds = 0;
    SvmModel trained = train_svm(set, options, HandImageOptions{}, HandGeometry{});
    fs::create_directories(model_dir() + "/models");
    trained.save(model_dir() + "/models/toy.model");
    return trained;
  }();
  return model;
}

class HogSvmTest : public ::testing::Test {
 protected:
  HogSvmTest() : host_(std::vector<std::string>{}) {
    host_.load_library(std::string(ANTIPODE_TEST_PLUGIN_DIR) + "/" +
                       plugin_file_name("hog_svm_classifier"));
    toy_model();
  }

  std::shared_ptr<Classifier> create(const std::string& yaml,
                                     const std::string& file = "tree.yaml") {
    return std::dynamic_pointer_cast<Classifier>(host_.create(
        "hog_svm_classifier", Parameters(YAML::Load(yaml), "component 'classifier'", file)));
  }

  std::string model_yaml() const { return "model: " + model_dir() + "/models/toy.model"; }

  PluginHost host_;
};

TEST_F(HogSvmTest, ScoresAreTheModelsDecisionValuesAndLabelsFollowTheThreshold) {
  ASSERT_EQ(host_.kind_of("hog_svm_classifier"), ComponentKind::kClassifier);
  const ToyHands toy = toy_hands(60, 2);
  HandSet set = toy.set;
  create(model_yaml())->classify(set, {});
  const auto expected =
      toy_model().decision_values(hand_descriptors(toy.set, HandGeometry{}, {}, 1), 1);
  ASSERT_EQ(set.hands.size(), toy.set.hands.size());
  int right = 0;
  for (std::size_t i = 0; i < set.hands.size(); ++i) {
    const Hand& hand = set.hands[i];
    EXPECT_EQ(hand.score, expected[i]) << i;
    EXPECT_EQ(hand.sample_index, toy.set.hands[i].sample_index);  // order kept
    EXPECT_EQ(hand.label, hand.score >= 0.0 ? HandLabel::kPositive : HandLabel::kNegative);
    EXPECT_EQ(hand.rejection, hand.score >= 0.0 ? Rejection::kNone : Rejection::kLowScore);
    right += (hand.label == HandLabel::kPositive) == toy.positive[i];
  }
  EXPECT_GE(right, 58);  // held-out hands at new poses
  HandSet strict = toy.set;
  create(model_yaml() + "\nthreshold: 1e9\nthreads: 1")->classify(strict, {});
  for (std::size_t i = 0; i < strict.hands.size(); ++i) {
    EXPECT_EQ(strict.hands[i].label, HandLabel::kNegative);
    EXPECT_EQ(strict.hands[i].score, set.hands[i].score);  // any thread count
  }
  HandSet empty;
  EXPECT_NO_THROW(create(model_yaml())->classify(empty, {}));
}

TEST_F(HogSvmTest, RelativeModelPathsAreFoundBesideTheTreeFile) {
  const ToyHands toy = toy_hands(4, 3);
  for (const std::string tree : {"/trees/x.yaml", "/models/x.yaml", "/x.yaml"}) {
    HandSet set = toy.set;
    create("model: models/toy.model", model_dir() + tree)->classify(set, {});
    EXPECT_NE(set.hands[0].label, HandLabel::kUnknown) << tree;
  }
}

TEST_F(HogSvmTest, BadModelsAndParametersAreErrorsAtTheirKeys) {
  const std::string missing = error_of([&] { create("threads: 1\nmodel: nowhere.model"); });
  EXPECT_NE(missing.find("tree.yaml:2:1: parameter 'model': nowhere.model"), std::string::npos)
      << missing;
  EXPECT_NE(missing.find("cannot open classifier model file"), std::string::npos) << missing;
  EXPECT_NE(missing.find("antipode train"), std::string::npos) << missing;
  const std::string corrupt_path = model_dir() + "/corrupt.model";
  {
    std::ifstream in(model_dir() + "/models/toy.model", std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes[bytes.size() / 3] = static_cast<char>(bytes[bytes.size() / 3] ^ 1);
    std::ofstream(corrupt_path, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const std::string corrupt = error_of([&] { create("model: " + corrupt_path); });
  EXPECT_NE(corrupt.find("tree.yaml:1:1:"), std::string::npos) << corrupt;
  EXPECT_NE(corrupt.find("corrupted (checksum mismatch)"), std::string::npos) << corrupt;
  EXPECT_NE(error_of([&] {
              create(model_yaml() + "\nthreshhold: 1");
            }).find("unknown parameter 'threshhold'"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              create(model_yaml() + "\nthreads: -1");
            }).find("parameter 'threads' must be in 0..256 (0: one per core), got -1"),
            std::string::npos);
  EXPECT_NE(error_of([&] { create(model_yaml() + "\nthreshold: .nan"); }).find("finite"),
            std::string::npos);
  const std::string veto = error_of([&] { create(model_yaml() + "\nantipodal_veto: often"); });
  EXPECT_NE(veto.find("antipodal_veto"), std::string::npos) << veto;
}

// With `score: probability` a calibrated model scores each hand by its Platt probability and
// labels by a threshold in 0..1 (0.5 unless given); an uncalibrated model is refused.
TEST_F(HogSvmTest, ProbabilityScoresComeFromTheModelsCalibration) {
  SvmModel calibrated = toy_model();
  calibrated.calibration = {-2.0, 0.25, 100};
  const std::string path = model_dir() + "/models/calibrated.model";
  calibrated.save(path);
  const ToyHands toy = toy_hands(20, 4);
  HandSet decision = toy.set, probability = toy.set;
  create(model_yaml())->classify(decision, {});
  create("model: " + path + "\nscore: probability")->classify(probability, {});
  for (std::size_t i = 0; i < probability.hands.size(); ++i) {
    const double p = 1.0 / (1.0 + std::exp(-2.0 * decision.hands[i].score + 0.25));
    EXPECT_NEAR(probability.hands[i].score, p, 1e-12) << i;
    EXPECT_EQ(probability.hands[i].label, p >= 0.5 ? HandLabel::kPositive : HandLabel::kNegative);
  }
  const std::string uncalibrated = error_of([&] { create(model_yaml() + "\nscore: probability"); });
  EXPECT_NE(uncalibrated.find("parameter 'score': probability needs a calibrated model, and"),
            std::string::npos)
      << uncalibrated;
  EXPECT_NE(error_of([&] {
              create("model: " + path + "\nscore: odds");
            }).find("parameter 'score' must be decision or probability, got 'odds'"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              create("model: " + path + "\nscore: probability\nthreshold: 2");
            }).find("so it must be in 0..1, got 2"),
            std::string::npos);
}

// A model file's operating points are the classifier's defaults: how to read the score and
// the thresholds of `operating_point` accept and relaxed. Explicit parameters still win.
TEST_F(HogSvmTest, TheModelFilesOperatingPointsAreTheDefaults) {
  SvmModel outcome = toy_model();
  outcome.calibration = {-1.0, 0.5, 100};
  outcome.operating = {true, 0.7, 0.4};
  const std::string path = model_dir() + "/models/operating.model";
  outcome.save(path);
  const ToyHands toy = toy_hands(40, 5);
  HandSet accept = toy.set, relaxed = toy.set, decision = toy.set;
  create("model: " + path)->classify(accept, {});
  create("model: " + path + "\noperating_point: relaxed")->classify(relaxed, {});
  create("model: " + path + "\nscore: decision")->classify(decision, {});
  EXPECT_EQ(accept.scores, ScoreMeaning::kProbability);
  EXPECT_EQ(decision.scores, ScoreMeaning::kOrder);
  int between = 0;
  for (std::size_t i = 0; i < accept.hands.size(); ++i) {
    const double p = accept.hands[i].score;
    EXPECT_NEAR(p, 1.0 / (1.0 + std::exp(-decision.hands[i].score + 0.5)), 1e-12);
    EXPECT_EQ(accept.hands[i].label, p >= 0.7 ? HandLabel::kPositive : HandLabel::kNegative);
    EXPECT_EQ(relaxed.hands[i].label, p >= 0.4 ? HandLabel::kPositive : HandLabel::kNegative);
    EXPECT_EQ(decision.hands[i].label,
              decision.hands[i].score >= 0.0 ? HandLabel::kPositive : HandLabel::kNegative);
    between += p >= 0.4 && p < 0.7;
  }
  EXPECT_GT(between, 0);  // the two operating points differ on these hands
  const std::string other_kind =
      error_of([&] { create("model: " + path + "\nscore: decision\noperating_point: relaxed"); });
  EXPECT_NE(other_kind.find("the model's operating points are not for this score; give a "
                            "'threshold'"),
            std::string::npos)
      << other_kind;
  EXPECT_NE(error_of([&] {
              create("model: " + path + "\noperating_point: lenient");
            }).find("parameter 'operating_point' must be accept or relaxed, got 'lenient'"),
            std::string::npos);
}

// `labels` picks among a robot file's models: its `model` (antipodal), its `success_model`
// (outcome), or the latter where the file names one.
TEST_F(HogSvmTest, LabelsChooseAmongTheRobotFilesModels) {
  SvmModel outcome = toy_model();
  outcome.calibration = {-2.0, 0.25, 100};
  outcome.operating = {true, 0.7, 0.4};
  outcome.save(model_dir() + "/models/success.model");
  const std::string source = ANTIPODE_TEST_SOURCE_DIR;
  const auto robot_file = [&](const std::string& name, const std::string& extra) {
    const std::string path = model_dir() + "/" + name;
    std::ofstream(path) << "urdf: " << source << "/robots/baxter/baxter.urdf\n"
                        << "arm_tip: right_gripper\ngripper_from: right_hand\n"
                        << "home_rad: [0.08, -1.0, 1.19, 1.94, -0.67, 1.03, 0.5]\n"
                        << "gripper: " << source << "/robots/grippers/baxter_electric.yaml\n"
                        << "model: models/toy.model\n"
                        << extra;
    return path;
  };
  const std::string both = robot_file("both.yaml", "success_model: models/success.model\n");
  const std::string one = robot_file("one.yaml", "");
  const ToyHands toy = toy_hands(10, 6);
  const auto meaning = [&](const std::string& yaml) {
    HandSet set = toy.set;
    create(yaml)->classify(set, {});
    return set.scores;
  };
  EXPECT_EQ(meaning("robot: " + both), ScoreMeaning::kOrder);  // antipodal by default
  EXPECT_EQ(meaning("robot: " + both + "\nlabels: outcome"), ScoreMeaning::kProbability);
  EXPECT_EQ(meaning("robot: " + both + "\nlabels: outcome_or_antipodal"),
            ScoreMeaning::kProbability);
  EXPECT_EQ(meaning("robot: " + one + "\nlabels: outcome_or_antipodal"), ScoreMeaning::kOrder);
  const std::string none = error_of([&] { create("robot: " + one + "\nlabels: outcome"); });
  EXPECT_NE(none.find("tree.yaml:2:1: parameter 'labels': " + one +
                      " names no success_model for its gripper; use labels: antipodal"),
            std::string::npos)
      << none;
  EXPECT_NE(error_of([&] { create("robot: " + both + "\nlabels: best"); })
                .find("parameter 'labels' must be antipodal, outcome or outcome_or_antipodal, got "
                      "'best'"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              create(model_yaml() + "\nlabels: outcome");
            }).find("parameter 'labels' chooses among the models of a robot file"),
            std::string::npos);
}

// The shipped grasp-success models are calibrated and read as probabilities at the
// operating points trees/train_outcomes.yaml writes (0.7, 0.4), each for the gripper it was
// trained with, and refuse the other's hands.
TEST(ShippedSuccessModelsTest, AreCalibratedProbabilitiesForTheirGrippers) {
  const std::string source = ANTIPODE_TEST_SOURCE_DIR;
  const std::string baxter = "robots/grippers/baxter_electric.yaml";
  const std::string wide = "robots/grippers/parallel_8cm.yaml";
  const std::string franka = "robots/grippers/franka_hand.yaml";
  for (const auto& [model_file, gripper, other] :
       {std::tuple<std::string, std::string, std::string>{"models/hog_svm_outcome.model", baxter,
                                                          wide},
        {"models/hog_svm_8cm_outcome.model", wide, baxter},
        {"models/hog_svm_franka_outcome.model", franka, wide}}) {
    const SvmModel model = SvmModel::load(source + "/" + model_file);
    EXPECT_TRUE(model.calibration.fitted()) << model_file;
    EXPECT_LT(model.calibration.a, 0.0) << model_file;  // larger decision values hold more
    EXPECT_TRUE(model.operating.probability) << model_file;
    EXPECT_DOUBLE_EQ(model.operating.accept, 0.7) << model_file;
    EXPECT_DOUBLE_EQ(model.operating.relaxed, 0.4) << model_file;
    const auto geometry = [&](const std::string& file) {
      return read_gripper_file(source + "/" + file).geometry;
    };
    EXPECT_NO_THROW(model.check_compatible(model.descriptor.image, geometry(gripper)));
    EXPECT_THROW(model.check_compatible(model.descriptor.image, geometry(other)), Error);
  }
}

TEST_F(HogSvmTest, AHandSetOfAnotherGeometryIsRefused) {
  HandSet set = toy_hands(3, 4).set;
  set.geometry.depth_m = 0.05;
  const std::string error = error_of([&] { create(model_yaml())->classify(set, {}); });
  EXPECT_NE(error.find("toy.model was trained for a 0.06 m deep"), std::string::npos) << error;
  EXPECT_NE(error.find("this hand set has a 0.05 m deep"), std::string::npos) << error;
}

// One hand at the origin (approach +x, closing +y) whose closing region holds a 2 mm grid of
// points: two faces of a 4 cm block facing the fingers (`faces_fingers`), or one flat face
// across the closing direction, whose normals no finger presses along.
HandSet one_hand_on_a_patch(bool faces_fingers) {
  auto cloud = std::make_shared<Cloud>();
  Hand hand;
  for (double x = 0.01; x <= 0.05; x += 0.002)
    for (double t = -0.01; t <= 0.0101; t += 0.002) {
      if (faces_fingers) {
        cloud->points_m.emplace_back(float(x), -0.02f, float(t));
        cloud->points_m.emplace_back(float(x), 0.02f, float(t));
      } else {
        cloud->points_m.emplace_back(float(x), float(2.0 * t), 0.0f);
      }
    }
  for (std::size_t i = 0; i < cloud->size(); ++i) hand.closing_points.push_back(std::int32_t(i));
  HandSet set;
  set.cloud = cloud;
  set.hands.push_back(hand);
  return set;
}

TEST_F(HogSvmTest, TheAntipodalVetoRejectsAcceptedHandsNoViewCouldMakeAntipodal) {
  const std::string accept_all = model_yaml() + "\nthreshold: -1e9";
  for (const bool faces_fingers : {true, false}) {
    HandSet plain = one_hand_on_a_patch(faces_fingers);
    create(accept_all)->classify(plain, {});
    EXPECT_EQ(plain.hands[0].label, HandLabel::kPositive);
    HandSet vetoed = one_hand_on_a_patch(faces_fingers);
    create(accept_all + "\nantipodal_veto: true")->classify(vetoed, {});
    EXPECT_EQ(vetoed.hands[0].score, plain.hands[0].score) << "the model's score stays";
    EXPECT_EQ(vetoed.hands[0].label, faces_fingers ? HandLabel::kPositive : HandLabel::kNegative);
    EXPECT_EQ(vetoed.hands[0].rejection,
              faces_fingers ? Rejection::kNone : Rejection::kNotAntipodal);
  }
}

}  // namespace
}  // namespace antipode
