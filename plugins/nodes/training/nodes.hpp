#pragma once
// The training nodes: behaviour-tree leaves that label hands, collect HOG examples, and train
// and evaluate the SVM classifier (docs/training.md). One registration function per node.

#include <cstdio>
#include <memory>
#include <string>

#include "antipode/bt/node_registry.hpp"
#include "antipode/grasp/training_set.hpp"

namespace antipode::training {

/// How a training set travels between nodes: shared and appended to in place by
/// CollectExamples (one set grows over a loop of scenes).
using TrainingSetPtr = std::shared_ptr<TrainingSet>;

/// "95.12%" for 0.9512: how the nodes print accuracies.
inline std::string percent(double fraction) {
  char text[16];
  std::snprintf(text, sizeof(text), "%.2f%%", 100.0 * fraction);
  return text;
}

void register_new_training_set(bt::NodeRegistry& registry);
void register_label_hands(bt::NodeRegistry& registry);
void register_collect_examples(bt::NodeRegistry& registry);
void register_save_training_set(bt::NodeRegistry& registry);
void register_load_training_set(bt::NodeRegistry& registry);
void register_new_trial_log(bt::NodeRegistry& registry);
void register_collect_trials(bt::NodeRegistry& registry);
void register_save_trials(bt::NodeRegistry& registry);
void register_merge_trials(bt::NodeRegistry& registry);
void register_train_classifier(bt::NodeRegistry& registry);
void register_evaluate_classifier(bt::NodeRegistry& registry);
void register_calibrate_classifier(bt::NodeRegistry& registry);
void register_cross_validate(bt::NodeRegistry& registry);

}  // namespace antipode::training
