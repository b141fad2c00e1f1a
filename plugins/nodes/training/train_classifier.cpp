#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "antipode/grasp/svm_training.hpp"
#include "fold_check.hpp"
#include "nodes.hpp"
#include "svm_node.hpp"

namespace antipode::training {
namespace {

/// Trains the HOG + SVM classifier on a training set and writes the model file.
class TrainClassifier final : public SvmNode {
 public:
  using SvmNode::SvmNode;
  static bt::NodeManifest manifest() {
    return {"TrainClassifier",
            bt::NodeCategory::kAction,
            ports(),
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
  static std::vector<bt::PortInfo> ports() {
    std::vector<bt::PortInfo> ports = {
        bt::input_port<TrainingSetPtr>("dataset", "the examples"),
        bt::input_port<std::string>("model_file", "where to write the model")};
    for (bt::PortInfo& port : svm_ports()) ports.push_back(std::move(port));
    ports.push_back(
        bt::input_port<std::string>("description", std::string{}, "free text stored in the model"));
    ports.push_back(bt::input_port<int>("size_budget_kib", 5120,
                                        "warn when the model file is larger (0: never)"));
    return ports;
  }

  SvmTrainingOptions read_options(const TrainingSet& set) const {
    SvmTrainingOptions o = read_svm_options();
    o.description = get_input<std::string>("description");
    if (o.description.empty()) {
      o.description = std::to_string(set.size()) + " examples from antipode train";
    }
    o.progress = [this](std::size_t done, std::size_t total, const std::string&) {
      progress(done, total, "training the SVM");
    };
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
