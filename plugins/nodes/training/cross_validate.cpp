#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "antipode/grasp/svm_training.hpp"
#include "fold_check.hpp"
#include "kernel_names.hpp"
#include "nodes.hpp"
#include "svm_node.hpp"

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
class CrossValidate final : public SvmNode {
 public:
  using SvmNode::SvmNode;
  static bt::NodeManifest manifest() {
    return {"CrossValidate",
            bt::NodeCategory::kAction,
            ports(),
            0,
            0,
            "Reports the SVM's cross-validation accuracy for each kernel, C and gamma.",
            {}};
  }

 protected:
  bt::Status tick() override {
    SvmTrainingOptions o = read_svm_options();
    if (o.folds < 2) fail("folds", "folds must be at least 2 to cross-validate");
    o.progress = [this](std::size_t done, std::size_t total, const std::string&) {
      progress(done, total, "cross-validation");
    };
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    if (const std::string problem = fold_problem(*set, o); !problem.empty()) {
      fail("folds_by", problem);
    }
    const CrossValidationResult result = cross_validate(*set, o);
    const std::string by = get_input<std::string>("folds_by");
    for (const auto& point : result.points) log(line(point, result.folds, by));
    return bt::Status::kSuccess;
  }

 private:
  static std::vector<bt::PortInfo> ports() {
    std::vector<bt::PortInfo> ports = {bt::input_port<TrainingSetPtr>("dataset", "the examples")};
    for (bt::PortInfo& port : svm_ports()) ports.push_back(std::move(port));
    return ports;
  }
};

}  // namespace

void register_cross_validate(bt::NodeRegistry& registry) {
  registry.register_node<CrossValidate>();
}

}  // namespace antipode::training
