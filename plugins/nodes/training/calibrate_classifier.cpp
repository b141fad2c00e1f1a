#include <optional>
#include <string>
#include <vector>

#include "antipode/bt/action_node.hpp"
#include "antipode/grasp/calibration.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "nodes.hpp"
#include "scored_examples.hpp"

namespace antipode::training {
namespace {

/// Makes a model's score a probability of success: fits Platt scaling to its decision values
/// on outcome-labelled examples it was not trained on (scenes held out from training) and
/// writes the model with it (SvmModel::calibration). `hog_svm_classifier` with `score:
/// probability` then scores hands by that probability. Given `accept` and `relaxed`, the model
/// is also written to be read that way by default (SvmModel::operating): probabilities, a
/// hand a grasp from `accept`, a second chance from `relaxed`.
class CalibrateClassifier final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"CalibrateClassifier",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("model_file", "the model to calibrate"),
             bt::input_port<TrainingSetPtr>(
                 "dataset", "outcome-labelled examples from scenes the model was not trained on"),
             bt::input_port<std::string>("calibrated_file", std::string{},
                                         "where to write the calibrated model (empty: model_file)"),
             bt::input_port<double>("accept", -1.0,
                                    "the probability from which a hand is a grasp, stored as the "
                                    "model's operating point (negative: keep the model's)"),
             bt::input_port<double>("relaxed", -1.0,
                                    "the second chance's probability threshold, likewise"),
             bt::input_port<int>("threads", 0, "workers (0: all cores)")},
            0,
            0,
            "Fits a model's probability of success on held-out outcomes (Platt scaling).",
            {}};
  }

 protected:
  // `accept` and `relaxed` together make probabilities the model's default reading; checked
  // before the examples are scored.
  std::optional<SvmOperatingPoints> operating_points() const {
    const double accept = get_input<double>("accept");
    const double relaxed = get_input<double>("relaxed");
    if (accept < 0.0 && relaxed < 0.0) return std::nullopt;
    if (!(accept >= 0.0 && accept <= 1.0))
      fail("accept", "port 'accept' is a probability in 0..1, got " + std::to_string(accept) +
                         " (give accept and relaxed, or neither to keep the model's)");
    if (!(relaxed >= 0.0 && relaxed <= accept))
      fail("relaxed", "port 'relaxed' is a probability in 0..accept (" + std::to_string(accept) +
                          "), got " + std::to_string(relaxed));
    return SvmOperatingPoints{true, accept, relaxed};
  }

  bt::Status tick() override {
    const std::string model_file = get_input<std::string>("model_file");
    std::string out = get_input<std::string>("calibrated_file");
    if (out.empty()) out = model_file;
    const std::optional<SvmOperatingPoints> operating = operating_points();
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    SvmModel model = SvmModel::load(model_file);
    model.check_compatible(set->descriptor, set->geometry, model_file);
    const ScoredExamples scored = score_examples(model, *set, get_input<int>("threads"));
    if (!scored.has_both_outcomes()) {
      fail("dataset", "calibration needs trials that held and trials that failed; the " +
                          std::to_string(set->size()) + " examples hold " +
                          std::to_string(set->positives()) + " successes");
    }
    model.calibration = fit_platt_scaling(scored.values, scored.held);
    if (operating) model.operating = *operating;
    model.save(out);
    const std::vector<double> p = model.calibration.probabilities(scored.values);
    log("calibrated on " + std::to_string(set->size()) + " held-out examples (" +
        percent(double(set->positives()) / double(set->size())) +
        " held): P(success) = 1 / (1 + exp(" + std::to_string(model.calibration.a) + " f + " +
        std::to_string(model.calibration.b) + ")); area under the ROC curve " +
        std::to_string(roc_auc(scored.values, scored.held)) +
        "; calibration error on these examples " +
        percent(calibration_error(calibration_table(p, scored.held))) + "; written to " + out);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_calibrate_classifier(bt::NodeRegistry& registry) {
  registry.register_node<CalibrateClassifier>();
}

}  // namespace antipode::training
