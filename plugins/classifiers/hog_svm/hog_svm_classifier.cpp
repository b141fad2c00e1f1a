// The classifier `hog_svm_classifier`: the paper's "SVM" configuration. Each hand's grasp
// hypothesis image is encoded by its HOG descriptor and scored by a trained polynomial-kernel
// SVM; see antipode/grasp/svm_model.hpp and docs/classification.md.
//
// Parameters: model (path; default: the `robot` file's model, else "models/hog_svm.model"),
// robot (a robot file, docs/robot.md: its models are the default), labels (which of the robot
// file's models: "antipodal", its `model`, the default; "outcome", its `success_model`;
// "outcome_or_antipodal", the success model where the file names one, else its `model`),
// score ("decision": the SVM's decision value; "probability": the calibrated probability of
// success of a model trained on outcome labels, docs/training.md; default: as the model file
// says), operating_point ("accept" or "relaxed": which of the model file's thresholds is the
// default threshold), threshold (the score from which a hand is a grasp; default: the model's
// operating point, or 0 for decision values and 0.5 for probabilities of a model read the
// other way), antipodal_veto (false; true: a hand the model accepts is still rejected when
// the near-antipodal check on the hand set's cloud finds it negative), threads (0 = all).
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

// `labels`, checked whatever model is used: one of the three, and only beside a robot file.
std::string read_labels(const Parameters& params) {
  const std::string labels = params.get<std::string>("labels", "antipodal");
  if (labels != "antipodal" && labels != "outcome" && labels != "outcome_or_antipodal") {
    params.fail("labels",
                "parameter 'labels' must be antipodal, outcome or "
                "outcome_or_antipodal, got '" +
                    labels + "'");
  }
  if (params.has("labels") && !params.has("robot")) {
    params.fail("labels",
                "parameter 'labels' chooses among the models of a robot file: give "
                "the classifier a 'robot'");
  }
  return labels;
}

// The robot file's model for `labels`.
std::string robot_model_path(const Parameters& params, const std::string& labels) {
  const RobotFile robot = robot_file_parameter(params, "robot");
  if (labels != "antipodal" && !robot.success_model_path.empty()) return robot.success_model_path;
  if (labels == "outcome") {
    params.fail("labels", "parameter 'labels': " + robot.path +
                              " names no success_model for its gripper; use labels: antipodal, "
                              "or train one (docs/training.md, outcome labels)");
  }
  if (robot.model_path.empty()) {
    params.fail("robot", "parameter 'robot': " + robot.path +
                             " names no model for its gripper; give the classifier a 'model'");
  }
  return robot.model_path;
}

// The model file: `model`, else the robot file's for `labels`, else the shipped model for
// Baxter's gripper. A `model` given beside a robot file replaces its models.
std::string model_path(const Parameters& params) {
  const std::string labels = read_labels(params);
  if (params.has("robot") && !params.has("model")) return robot_model_path(params, labels);
  (void)params.get<std::string>("robot", "");  // read: replaced by `model`
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
  const std::string score =
      params.get<std::string>("score", model.operating.probability ? "probability" : "decision");
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

// The threshold: `threshold`, else the model's operating point when the score is read as the
// model says, else 0 (decision values) or 0.5 (probabilities).
double read_threshold(const Parameters& params, const SvmModel& model, bool probability) {
  const std::string point = params.get<std::string>("operating_point", "accept");
  if (point != "accept" && point != "relaxed") {
    params.fail("operating_point",
                "parameter 'operating_point' must be accept or relaxed, got '" + point + "'");
  }
  const bool relaxed = point == "relaxed";
  if (params.has("threshold")) return params.get<double>("threshold", 0.0);
  if (probability == model.operating.probability)
    return relaxed ? model.operating.relaxed : model.operating.accept;
  if (relaxed) {
    params.fail("operating_point",
                "parameter 'operating_point': the model's operating points "
                "are not for this score; give a 'threshold'");
  }
  return probability ? 0.5 : 0.0;
}

class HogSvmClassifier final : public Classifier {
 public:
  explicit HogSvmClassifier(const Parameters& params)
      : path_(model_path(params)),
        model_(load_model(params, path_)),
        probability_(read_score(params, model_, path_)),
        threshold_(read_threshold(params, model_, probability_)),
        antipodal_veto_(params.get<bool>("antipodal_veto", false)),
        threads_(params.get<int>("threads", 0)) {
    if (!std::isfinite(threshold_))
      params.fail("threshold", "parameter 'threshold' must be finite");
    if (probability_ && !(threshold_ >= 0.0 && threshold_ <= 1.0))
      params.fail("threshold",
                  "parameter 'threshold' is a probability (score: probability, " +
                      std::string(params.has("score") ? "as given" : "as " + path_ + " says") +
                      "), so it must be in 0..1, got " + std::to_string(threshold_) +
                      " (for a decision value, give score: decision)");
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
    set.scores = probability_ ? ScoreMeaning::kProbability : ScoreMeaning::kOrder;
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
    HandSet accepted{set.cloud, {}, set.geometry, set.support, {}, set.scores};
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

ANTIPODE_PLUGIN_WITH_CHECKS("hog_svm_classifier", "1.1.0", kFactories, kChecks)
