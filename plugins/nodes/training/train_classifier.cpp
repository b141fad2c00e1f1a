#include <cmath>
#include <cstdio>
#include <filesystem>

#include "antipode/bt/action_node.hpp"
#include "antipode/grasp/svm_training.hpp"
#include "fold_check.hpp"
#include "kernel_names.hpp"
#include "nodes.hpp"

namespace antipode::training {
namespace {

/// Trains the HOG + SVM classifier on a training set and writes the model file.
class TrainClassifier final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    const SvmTrainingOptions d;
    return {
        "TrainClassifier",
        bt::NodeCategory::kAction,
        {bt::input_port<TrainingSetPtr>("dataset", "the examples"),
         bt::input_port<std::string>("model_file", "where to write the model"),
         bt::input_port<std::vector<std::string>>(
             "kernels", std::vector<std::string>{"poly"},
             "kernel families tried by cross-validation: poly, rbf (Gaussian)"),
         bt::input_port<int>("degree", d.degree, "polynomial kernel degree"),
         bt::input_port<std::vector<double>>("c_values", d.c_values,
                                             "soft-margin costs tried by cross-validation"),
         bt::input_port<std::vector<double>>("gamma_values", d.gamma_values,
                                             "kernel scales tried; empty = 1 / components"),
         bt::input_port<int>("components", static_cast<int>(d.pca_components),
                             "PCA components the descriptors are reduced to"),
         bt::input_port<int>("folds", d.folds, "cross-validation folds (0: none)"),
         bt::input_port<std::string>("folds_by", std::string("scene"),
                                     "what a fold keeps together while C is chosen: "
                                     "scene (objects held out), hand or example"),
         bt::input_port<int>("cache_mib", static_cast<int>(d.cache_mib),
                             "kernel row cache of each solver in MiB (a fold per worker)"),
         bt::input_port<double>("positive_weight", d.positive_weight,
                                "C of grasps over C of non-grasps (above 1: a missed grasp "
                                "costs more)"),
         bt::input_port<int>("threads", 0, "workers (0: all cores)"),
         bt::input_port<std::string>("description", std::string{}, "free text stored in the model"),
         bt::input_port<int>("size_budget_kib", 5120,
                             "warn when the model file is larger (0: never)")},
        0,
        0,
        "Trains the SVM grasp classifier (C chosen by cross-validation) and writes it.",
        {}};
  }

 protected:
  bt::Status tick() override {
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    const std::string file = get_input<std::string>("model_file");
    if (file.empty()) fail("model_file", "model_file is empty");
    const int budget_kib = get_input<int>("size_budget_kib");
    if (budget_kib < 0) fail("size_budget_kib", "size_budget_kib must be 0 or more");
    const SvmTrainingOptions options = read_options(*set);
    log("training on " + std::to_string(set->size()) + " examples (" +
        std::to_string(set->positives()) + " positive, " + std::to_string(set->negatives()) +
        " negative)");
    if (const std::string problem = fold_problem(*set, options); !problem.empty()) {
      fail("folds_by", problem);
    }
    const SvmModel model = train_svm(*set, options);
    model.save(file);
    log(model_summary(model, file));
    if (const std::string warning = over_budget(model, file, budget_kib); !warning.empty()) {
      log(warning);
    }
    return bt::Status::kSuccess;
  }

 private:
  SvmTrainingOptions read_options(const TrainingSet& set) const {
    SvmTrainingOptions o;
    try {
      o.kernels = kernel_types(get_input<std::vector<std::string>>("kernels"));
    } catch (const Error& e) {
      fail("kernels", e.message());
    }
    o.degree = get_input<int>("degree");
    o.c_values = get_input<std::vector<double>>("c_values");
    o.gamma_values = get_input<std::vector<double>>("gamma_values");
    const int components = get_input<int>("components");
    if (components < 1) fail("components", "components must be at least 1");
    o.pca_components = static_cast<std::size_t>(components);
    o.folds = get_input<int>("folds");
    try {
      o.folds_by = fold_unit(get_input<std::string>("folds_by"));
    } catch (const Error& e) {
      fail("folds_by", e.message());
    }
    const int cache_mib = get_input<int>("cache_mib");
    if (cache_mib < 1) fail("cache_mib", "cache_mib must be at least 1");
    o.cache_mib = static_cast<std::size_t>(cache_mib);
    o.positive_weight = get_input<double>("positive_weight");
    if (!(o.positive_weight > 0.0 && std::isfinite(o.positive_weight))) {
      fail("positive_weight", "positive_weight must be positive");
    }
    o.threads = get_input<int>("threads");
    o.seed = random().next_u64();
    o.description = get_input<std::string>("description");
    if (o.description.empty()) {
      o.description = std::to_string(set.size()) + " examples from antipode train";
    }
    o.progress = [this](std::size_t done, std::size_t total, const std::string&) {
      progress(done, total, "training the SVM");
    };
    try {
      o.validate();
    } catch (const Error& e) {
      fail("c_values", e.message());
    }
    return o;
  }

  // A model to ship has a size budget (5 MB), and its size grows with the support vectors:
  // a warning when the written file is over it, else "".
  static std::string over_budget(const SvmModel& model, const std::string& file, int budget_kib) {
    std::error_code error;
    const auto bytes = std::filesystem::file_size(file, error);
    if (budget_kib == 0 || error || bytes <= static_cast<std::uintmax_t>(budget_kib) * 1024) {
      return {};
    }
    return "warning: " + file + " is " + std::to_string(bytes / 1024) + " KiB, over the " +
           std::to_string(budget_kib) + " KiB budget (size_budget_kib); " +
           std::to_string(model.support_vector_count()) +
           " support vectors - fewer examples, components or a larger C make a smaller model";
  }

  static std::string model_summary(const SvmModel& model, const std::string& file) {
    std::string text = std::string(kernel_name(model.kernel.type)) +
                       " kernel, C = " + std::to_string(model.kernel.C) +
                       ", gamma = " + std::to_string(model.kernel.gamma) + ", " +
                       std::to_string(model.support_vector_count()) + " support vectors, " +
                       std::to_string(model.components()) + " components";
    if (model.info.cv_accuracy >= 0.0) {
      text += "; cross-validation accuracy " + percent(model.info.cv_accuracy);
    }
    std::error_code error;
    const auto bytes = std::filesystem::file_size(file, error);
    return text + "; " + file + (error ? "" : " (" + std::to_string(bytes / 1024) + " KiB)");
  }
};

}  // namespace

void register_train_classifier(bt::NodeRegistry& registry) {
  registry.register_node<TrainClassifier>();
}

}  // namespace antipode::training
