// NewTrainingSet, SaveTrainingSet and LoadTrainingSet: where a training set starts and how it
// is kept between runs (so a classifier can be retrained without rendering again).
#include "antipode/bt/action_node.hpp"
#include "nodes.hpp"

namespace antipode::training {
namespace {

std::string summary(const TrainingSet& set) {
  return std::to_string(set.size()) + " examples (" + std::to_string(set.positives()) +
         " positive, " + std::to_string(set.negatives()) + " negative)";
}

/// Starts an empty training set.
class NewTrainingSet final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"NewTrainingSet",
            bt::NodeCategory::kAction,
            {bt::output_port<TrainingSetPtr>("dataset", "an empty training set")},
            0,
            0,
            "Starts an empty training set for CollectExamples to fill.",
            {}};
  }

 protected:
  bt::Status tick() override {
    set_output("dataset", std::make_shared<TrainingSet>());
    return bt::Status::kSuccess;
  }
};

/// Writes a training set to a file (antipode's binary training-set format).
class SaveTrainingSet final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SaveTrainingSet",
            bt::NodeCategory::kAction,
            {bt::input_port<TrainingSetPtr>("dataset", "the training set"),
             bt::input_port<std::string>("file", "where to write it; empty = nowhere")},
            0,
            0,
            "Writes a training set to a file, all-or-nothing.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    save_training_set(*set, file);
    log(summary(*set) + " written to " + file);
    return bt::Status::kSuccess;
  }
};

/// Reads a training set written by SaveTrainingSet.
class LoadTrainingSet final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"LoadTrainingSet",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("file", "a training-set file"),
             bt::output_port<TrainingSetPtr>("dataset", "its examples")},
            0,
            0,
            "Reads a training set from a file.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    auto set = std::make_shared<TrainingSet>(load_training_set(file));
    log(summary(*set) + " read from " + file);
    set_output("dataset", TrainingSetPtr(std::move(set)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_new_training_set(bt::NodeRegistry& registry) {
  registry.register_node<NewTrainingSet>();
}
void register_save_training_set(bt::NodeRegistry& registry) {
  registry.register_node<SaveTrainingSet>();
}
void register_load_training_set(bt::NodeRegistry& registry) {
  registry.register_node<LoadTrainingSet>();
}

}  // namespace antipode::training
