#include "scored_examples.hpp"

#include <algorithm>

namespace antipode::training {

bool ScoredExamples::has_both_outcomes() const {
  const auto wins = std::count(held.begin(), held.end(), true);
  return wins > 0 && wins < static_cast<long>(held.size());
}

ScoredExamples score_examples(const SvmModel& model, const TrainingSet& set, int threads) {
  set.validate();
  ScoredExamples scored;
  scored.values = model.decision_values(set.features.data(), set.size(), set.dimension, threads);
  scored.held.resize(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) scored.held[i] = set.labels[i] > 0;
  return scored;
}

}  // namespace antipode::training
