#include "fold_check.hpp"

#include "antipode/core/error.hpp"

namespace antipode::training {

std::string fold_problem(const TrainingSet& set, const SvmTrainingOptions& options) {
  if (options.folds < 2 || set.empty()) return {};
  try {
    assign_folds(set, options.folds, options.seed, options.folds_by);
  } catch (const Error& e) {
    std::string hint;
    if (options.folds_by == FoldUnit::kScene) {
      hint = "; give CollectExamples a different `source` per scene, or fold by hand";
    }
    return e.message() + hint;
  }
  return {};
}

}  // namespace antipode::training
