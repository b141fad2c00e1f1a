// The classifier `hog_svm_classifier`: the paper's "SVM" configuration. Each hand's grasp
// hypothesis image is encoded by its HOG descriptor and scored by a trained polynomial-kernel
// SVM; see antipode/grasp/svm_model.hpp and docs/classification.md.
//
// Parameters: model (path; default: the `robot` file's model, else "models/hog_svm.model"),
// robot (a robot file, docs/robot.md: its `model` is the default model), score ("decision": the
// SVM's decision value; "probability": the calibrated probability of success of a model trained on
// outcome labels, docs/training.md), threshold (the score from which a hand is a grasp: 0 for
// decision values, 0.5 for probabilities), antipodal_veto (false; true: a hand the model accepts
// is still rejected when the near-antipodal check on the hand set's cloud finds it negative),
// threads (0 = all).
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/grasp/antipodal.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/plugin/abi.hpp"
#include "antipode/robot/robot_file.hpp"

namespace {
using namespace antipode;
namespace fs = std::filesystem;

// The model file: `model`, else the robot file's, else the shipped model for Baxter's gripper.
std::string model_path(const Parameters& params) {
  const bool robot_model = params.has("robot") && !params.has("model");
  (void)params.get<std::string>("robot", "");  // a `model` given beside it replaces its model
  if (robot_model) {
    const RobotFile robot = robot_file_parameter(params, "robot");
    if (robot.model_path.empty()) {
      params.fail("robot", "parameter 'robot': " + robot.path +
                               " names no model for its gripper; give the classifier a 'model'");
    }
    return robot.model_path;
  }
  return resolve_path(params.get<std::string>("model", "models/hog_svm.model"), params.file());
}

SvmModel load_model(const Parameters& params, const std::string& path) {
  try {
    return SvmModel::load(path);
  } catch (const Error& e) {
    params.fail("model", std::string("parameter 'model': ") + e.what() +
                             (fs::exists(path) ? "" : " (train one with `antipode train`)"));
  }
}

// Whether the score is the decision value (false) or the probability of success (true).
bool read_score(const Parameters& params, const SvmModel& model, const std::string& path) {
  const std::string score = params.get<std::string>("score", "decision");
  if (score == "decision") return false;
  if (score != "probability") {
    params.fail("score", "parameter 'score' must be decision or probability, got '" + score + "'");
  }
  if (!model.calibration.fitted()) {
    params.fail("score", "parameter 'score': probability needs a calibrated model, and " + path +
                             " is not (calibrate it with trees/train_outcomes.yaml, "
                             "docs/training.md)");
  }
  return true;
}

class HogSvmClassifier final : public Classifier {
 public:
  explicit HogSvmClassifier(const Parameters& params)
      : path_(model_path(params)),
        model_(load_model(params, path_)),
        probability_(read_score(params, model_, path_)),
        threshold_(params.get<double>("threshold", probability_ ? 0.5 : 0.0)),
        antipodal_veto_(params.get<bool>("antipodal_veto", false)),
        threads_(params.get<int>("threads", 0)) {
    if (!std::isfinite(threshold_))
      params.fail("threshold", "parameter 'threshold' must be finite");
    if (probability_ && !(threshold_ >= 0.0 && threshold_ <= 1.0))
      params.fail("threshold",
                  "parameter 'threshold' is a probability (score: probability), "
                  "so it must be in 0..1, got " +
                      std::to_string(threshold_));
    if (threads_ < 0 || threads_ > 256) {
      params.fail("threads", "parameter 'threads' must be in 0..256 (0: one per core), got " +
                                 std::to_string(threads_));
    }
    params.reject_unknown();
  }

  // The model's own check, as one sentence: it names the command that trains a model for
  // `hand`.
  std::string hand_problem(const HandGeometry& hand) const override {
    try {
      model_.check_compatible(model_.descriptor.image, hand, "model " + path_);
    } catch (const Error& e) {
      return e.what();
    }
    return {};
  }

  void classify(HandSet& set, const StopToken& stop) const override {
    if (set.hands.empty()) return;
    model_.check_compatible(model_.descriptor.image, set.geometry, "model " + path_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    const auto descriptors = hand_descriptors(set, set.geometry, model_.descriptor.image, threads_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    const std::vector<double> values = model_.decision_values(descriptors, threads_);
    stop.throw_if_stop_requested("hog_svm_classifier");
    for (std::size_t i = 0; i < set.hands.size(); ++i) {
      Hand& hand = set.hands[i];
      hand.score = probability_ ? model_.calibration.probability(values[i]) : values[i];
      if (hand.score >= threshold_) {
        hand.label = HandLabel::kPositive;
      } else {
        hand.label = HandLabel::kNegative;
        hand.rejection = Rejection::kLowScore;
      }
    }
    if (antipodal_veto_) veto_not_antipodal(set, stop);
  }

 private:
  // The veto (docs/classification.md): the accepted hands whose closing region shows fewer
  // than k points facing either finger - no view could make them near antipodal - become
  // negative (`not_antipodal`); their score stays the model's.
  void veto_not_antipodal(HandSet& set, const StopToken& stop) const {
    HandSet accepted{set.cloud, {}, set.geometry, set.support, {}};
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < set.hands.size(); ++i)
      if (set.hands[i].label == HandLabel::kPositive) {
        accepted.hands.push_back(set.hands[i]);
        index.push_back(i);
      }
    if (index.empty()) return;
    AntipodalLabellingOptions options;
    options.normals.threads = threads_;
    const std::vector<AntipodalCount> counts = count_antipodal_normals(accepted, options);
    stop.throw_if_stop_requested("hog_svm_classifier");
    for (std::size_t j = 0; j < index.size(); ++j) {
      if (antipodal_label(counts[j], options.antipodal.min_points) != HandLabel::kNegative)
        continue;
      Hand& hand = set.hands[index[j]];
      hand.label = HandLabel::kNegative;
      hand.rejection = Rejection::kNotAntipodal;
    }
  }

  std::string path_;
  SvmModel model_;
  bool probability_;
  double threshold_;
  bool antipodal_veto_;
  int threads_;
};

Component* create_hog_svm(const Parameters& params) { return new HogSvmClassifier(params); }

// Reading the model is the check: its checksum, its sizes, its calibration for `score`.
void check_hog_svm(const Parameters& params) { const HogSvmClassifier checked(params); }

const PluginFactory kFactories[] = {
    {"classifier", "hog_svm_classifier",
     "labels hands by a trained SVM on HOG descriptors of their grasp images (the paper's SVM)",
     &create_hog_svm, nullptr},
};

const PluginParameterCheck kChecks[] = {{"hog_svm_classifier", &check_hog_svm}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("hog_svm_classifier", "1.0.0", kFactories, kChecks)
