#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/grasp/calibration.hpp"
#include "antipode/grasp/svm_training.hpp"
#include "nodes.hpp"
#include "scored_examples.hpp"

namespace antipode::training {
namespace {

nlohmann::json report(const ConfusionMatrix& c, const TrainingSet& set, const std::string& model) {
  return {{"model", model},
          {"examples", set.size()},
          {"positives", set.positives()},
          {"negatives", set.negatives()},
          {"accuracy", c.accuracy()},
          {"precision", c.precision()},
          {"recall", c.recall()},
          {"confusion", {{"tp", c.tp}, {"fp", c.fp}, {"tn", c.tn}, {"fn", c.fn}}}};
}

/// Measures a model on labelled examples: accuracy, precision, recall, confusion matrix, the
/// area under the ROC curve and, for a calibrated model, its calibration by decile.
class EvaluateClassifier final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"EvaluateClassifier",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("model_file", "the model to measure"),
             bt::input_port<TrainingSetPtr>("dataset", "labelled examples it never saw"),
             bt::input_port<double>("threshold", 0.0, "decision value from which a grasp"),
             bt::input_port<std::string>("report_file", std::string{},
                                         "also write the numbers as JSON (empty: no file)"),
             bt::input_port<int>("threads", 0, "workers (0: all cores)")},
            0,
            0,
            "Measures a classifier model on labelled examples (and its calibration).",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string model_file = get_input<std::string>("model_file");
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    const SvmModel model = SvmModel::load(model_file);
    model.check_compatible(set->descriptor, set->geometry, model_file);
    const ScoredExamples scored = score_examples(model, *set, get_input<int>("threads"));
    const ConfusionMatrix c = confusion(scored.values, set->labels, get_input<double>("threshold"));
    log(std::to_string(set->size()) + " examples (" + std::to_string(set->positives()) +
        " positive, " + std::to_string(set->negatives()) + " negative): accuracy " +
        percent(c.accuracy()) + ", precision " + percent(c.precision()) + ", recall " +
        percent(c.recall()));
    log("               classified grasp   classified not");
    log("  grasp        " + column(c.tp) + column(c.fn));
    log("  not a grasp  " + column(c.fp) + column(c.tn));
    nlohmann::json numbers = report(c, *set, model_file);
    if (scored.has_both_outcomes()) add_ranking(scored, model, numbers);
    write_report(numbers);
    return bt::Status::kSuccess;
  }

 private:
  // The area under the ROC curve, and for a calibrated model the calibration by decile.
  void add_ranking(const ScoredExamples& scored, const SvmModel& model,
                   nlohmann::json& numbers) const {
    const double auc = roc_auc(scored.values, scored.held);
    numbers["roc_auc"] = auc;
    log("area under the ROC curve " + fixed(auc, 3));
    if (!model.calibration.fitted()) return;
    const std::vector<CalibrationBin> table =
        calibration_table(model.calibration.probabilities(scored.values), scored.held);
    numbers["calibration_error"] = calibration_error(table);
    log("calibration by decile (mean predicted / observed, examples):");
    for (const CalibrationBin& bin : table) {
      log("  " + percent(bin.predicted) + " / " + percent(bin.observed) + "  (" +
          std::to_string(bin.count) + ")");
      numbers["calibration"].push_back(
          {{"predicted", bin.predicted}, {"observed", bin.observed}, {"count", bin.count}});
    }
    log("calibration error " + fixed(100.0 * calibration_error(table), 1) +
        " points (mean |predicted - observed| over the deciles)");
  }

  static std::string fixed(double value, int digits) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.*f", digits, value);
    return text;
  }

  static std::string column(std::uint64_t count) {
    char text[32];
    std::snprintf(text, sizeof(text), "%16llu   ", static_cast<unsigned long long>(count));
    return text;
  }

  void write_report(const nlohmann::json& numbers) const {
    const std::string file = get_input<std::string>("report_file");
    if (file.empty()) return;
    write_file_atomically(file, [&](const std::string& temporary) {
      std::ofstream out(temporary);
      out << numbers.dump(2) << '\n';
      out.flush();
      if (!out) throw Error("cannot write " + temporary);
    });
    log("report written to " + file);
  }
};

}  // namespace

void register_evaluate_classifier(bt::NodeRegistry& registry) {
  registry.register_node<EvaluateClassifier>();
}

}  // namespace antipode::training
