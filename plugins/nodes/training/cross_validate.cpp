#include <cmath>
#include <cstdio>

#include "antipode/bt/action_node.hpp"
#include "antipode/grasp/svm_training.hpp"
#include "fold_check.hpp"
#include "kernel_names.hpp"
#include "nodes.hpp"

namespace antipode::training {
namespace {

std::string line(const CrossValidationPoint& p, int folds, const std::string& by) {
  const ConfusionMatrix& c = p.confusion;
  char text[256];
  std::snprintf(
      text, sizeof(text),
      "%d-fold by %s, %s kernel, C %g, gamma %g: accuracy %.2f%%, precision %.2f%%, recall "
      "%.2f%% (tp %llu, fp %llu, tn %llu, fn %llu)",
      folds, by.c_str(), kernel_name(p.kernel), p.C, p.gamma, 100.0 * c.accuracy(),
      100.0 * c.precision(), 100.0 * c.recall(), static_cast<unsigned long long>(c.tp),
      static_cast<unsigned long long>(c.fp), static_cast<unsigned long long>(c.tn),
      static_cast<unsigned long long>(c.fn));
  return text;
}

/// Cross-validates the SVM on a training set, with folds drawn by example, hand or scene.
class CrossValidate final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    const SvmTrainingOptions d;
    return {
        "CrossValidate",
        bt::NodeCategory::kAction,
        {bt::input_port<TrainingSetPtr>("dataset", "the examples"),
         bt::input_port<std::string>("folds_by", std::string("scene"),
                                     "what a fold keeps together: scene (objects held out), "
                                     "hand (its C1, C2 and C12 descriptors) or example (the "
                                     "paper)"),
         bt::input_port<int>("folds", d.folds, "number of folds"),
         bt::input_port<std::vector<std::string>>("kernels", std::vector<std::string>{"poly"},
                                                  "kernel families to try: poly, rbf"),
         bt::input_port<std::vector<double>>("c_values", d.c_values, "costs to try"),
         bt::input_port<std::vector<double>>("gamma_values", d.gamma_values,
                                             "kernel scales to try; empty = 1 / components"),
         bt::input_port<int>("components", static_cast<int>(d.pca_components), "PCA components"),
         bt::input_port<int>("cache_mib", static_cast<int>(d.cache_mib),
                             "kernel row cache of each solver in MiB (a fold per worker)"),
         bt::input_port<double>("positive_weight", d.positive_weight,
                                "C of grasps over C of non-grasps (above 1: a missed grasp "
                                "costs more)"),
         bt::input_port<int>("threads", 0, "workers (0: all cores)")},
        0,
        0,
        "Reports the SVM's cross-validation accuracy for each kernel, C and gamma.",
        {}};
  }

 protected:
  bt::Status tick() override {
    const std::string by = get_input<std::string>("folds_by");
    SvmTrainingOptions o;
    try {
      o.folds_by = fold_unit(by);
    } catch (const Error& e) {
      fail("folds_by", e.message());
    }
    o.folds = get_input<int>("folds");
    try {
      o.kernels = kernel_types(get_input<std::vector<std::string>>("kernels"));
    } catch (const Error& e) {
      fail("kernels", e.message());
    }
    o.c_values = get_input<std::vector<double>>("c_values");
    o.gamma_values = get_input<std::vector<double>>("gamma_values");
    const int components = get_input<int>("components");
    if (components < 1) fail("components", "components must be at least 1");
    o.pca_components = static_cast<std::size_t>(components);
    const int cache_mib = get_input<int>("cache_mib");
    if (cache_mib < 1) fail("cache_mib", "cache_mib must be at least 1");
    o.cache_mib = static_cast<std::size_t>(cache_mib);
    o.positive_weight = get_input<double>("positive_weight");
    if (!(o.positive_weight > 0.0 && std::isfinite(o.positive_weight))) {
      fail("positive_weight", "positive_weight must be positive");
    }
    o.threads = get_input<int>("threads");
    o.seed = random().next_u64();
    o.progress = [this](std::size_t done, std::size_t total, const std::string&) {
      progress(done, total, "cross-validation");
    };
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    if (const std::string problem = fold_problem(*set, o); !problem.empty()) {
      fail("folds_by", problem);
    }
    const CrossValidationResult result = cross_validate(*set, o);
    for (const auto& point : result.points) log(line(point, result.folds, by));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_cross_validate(bt::NodeRegistry& registry) {
  registry.register_node<CrossValidate>();
}

}  // namespace antipode::training
