#include "antipode/evaluation/run_bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "antipode/core/random.hpp"

namespace antipode::evaluation {

std::pair<double, double> run_bootstrap_interval(const std::vector<RunCount>& runs, int resamples) {
  constexpr std::uint64_t kSeed = 20151;  // any fixed value: the interval must not vary
  RandomStream random(kSeed);
  std::vector<double> rates;
  rates.reserve(std::size_t(std::max(resamples, 0)));
  for (int draw = 0; draw < resamples && !runs.empty(); ++draw) {
    long long successes = 0, trials = 0;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const RunCount& run = runs[random.below(runs.size())];
      successes += run.successes;
      trials += run.trials;
    }
    if (trials > 0) rates.push_back(double(successes) / double(trials));
  }
  if (rates.empty()) return {0.0, 1.0};
  std::sort(rates.begin(), rates.end());
  const auto at = [&](double p) {
    const double rank = std::ceil(p * double(rates.size())) - 1.0;
    return rates[std::size_t(std::clamp(rank, 0.0, double(rates.size() - 1)))];
  };
  return {at(0.025), at(0.975)};
}

}  // namespace antipode::evaluation
