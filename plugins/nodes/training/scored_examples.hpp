#pragma once
// What the nodes that judge a model against outcomes (EvaluateClassifier, CalibrateClassifier)
// start from: the model's decision value for every example, and whether it was a success.

#include <vector>

#include "antipode/grasp/svm_model.hpp"
#include "antipode/grasp/training_set.hpp"

namespace antipode::training {

struct ScoredExamples {
  std::vector<double> values;  ///< the model's decision value of each example
  std::vector<bool> held;      ///< the example's label is +1 (a grasp that held)

  bool has_both_outcomes() const;
};

/// Scores every example of `set` (validated first) with `model`, using `threads` workers.
ScoredExamples score_examples(const SvmModel& model, const TrainingSet& set, int threads);

}  // namespace antipode::training
