#pragma once
// An interval for a rate pooled over runs that treats the runs, not the attempts, as the
// independent samples. The attempts of one clear-the-box run share its scene: a run that
// keeps failing on one object it cannot hold makes many failures of one cause, and a per-
// attempt interval (Wilson) is then too narrow.

#include <utility>
#include <vector>

namespace antipode::evaluation {

/// One run's count of successes in its trials (attempts, or objects placed).
struct RunCount {
  int successes = 0;
  int trials = 0;
};

/// The 95% percentile-bootstrap interval of sum(successes) / sum(trials) over `runs`,
/// resampled whole: `resamples` draws of as many runs with replacement, each draw's pooled
/// rate, their 2.5% and 97.5% quantiles. Deterministic (a fixed seed): the same runs give the
/// same interval. Draws without trials are left out. {0, 1} when no run has a trial.
std::pair<double, double> run_bootstrap_interval(const std::vector<RunCount>& runs,
                                                 int resamples = 2000);

}  // namespace antipode::evaluation
