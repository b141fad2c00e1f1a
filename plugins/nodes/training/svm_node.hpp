#pragma once
// The ports that TrainClassifier and CrossValidate share (the SVM's solver and model
// selection) and their reading into SvmTrainingOptions.

#include <vector>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/grasp/svm_training.hpp"

namespace antipode::training {

/// Base of the nodes that fit SVMs on a training set. A bad value is a tree error located
/// at its own port (`retrain.yaml:6:69: cache_mib must be at least 1`).
class SvmNode : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;

 protected:
  /// kernels, degree, c_values, gamma_values, components, folds, folds_by, cache_mib,
  /// positive_weight and threads, with SvmTrainingOptions' defaults (folds_by: scene).
  static std::vector<bt::PortInfo> svm_ports();

  /// Those ports read and checked; the seed is the node's next random number, so a tree's
  /// seed fixes the folds and the PCA subsample.
  SvmTrainingOptions read_svm_options() const;
};

}  // namespace antipode::training
