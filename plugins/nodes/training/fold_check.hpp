#pragma once
// Whether a training set can be cut into the cross-validation folds some options ask for.

#include <string>

#include "antipode/grasp/svm_training.hpp"

namespace antipode::training {

/// Empty when `set` has at least `options.folds` units of `options.folds_by` (or folds is
/// 0); otherwise what is wrong and how to fix it, for the node to report at `folds_by`.
std::string fold_problem(const TrainingSet& set, const SvmTrainingOptions& options);

}  // namespace antipode::training
