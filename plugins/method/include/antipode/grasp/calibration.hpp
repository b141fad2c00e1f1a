#pragma once
/// @file
/// Turning a classifier's decision values into probabilities of success, and measuring how
/// good those probabilities are. A model trained on outcome labels (a grasp held or not,
/// docs/training.md) gives decision values f; Platt scaling fits
///
///   P(success | f) = 1 / (1 + exp(a f + b))
///
/// on examples the model never saw (held-out scenes), by maximum likelihood with Platt's
/// smoothed targets. The measures judge any score against 0/1 outcomes: the area under the
/// ROC curve (does the score rank successes first?) and the calibration table (in each tenth
/// of the examples, ordered by predicted probability, how the mean prediction compares with
/// the observed success rate).
///
/// Everything here is deterministic and single-threaded; the functions throw antipode::Error
/// for mismatched lengths or non-finite numbers.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace antipode {

/// The sigmoid that maps a decision value to a probability of success. `examples` is 0 for a
/// model that was never calibrated (its decision values are then no probability).
struct PlattScaling {
  double a = 0.0;              ///< slope (negative when larger decision values mean success)
  double b = 0.0;              ///< offset
  std::uint64_t examples = 0;  ///< how many held-out examples the fit used

  bool fitted() const { return examples > 0; }
  /// 1 / (1 + exp(a f + b)), computed without overflow; in [0, 1].
  double probability(double decision_value) const;
  /// probability() of each decision value.
  std::vector<double> probabilities(const std::vector<double>& decision_values) const;
};

/// Fits `PlattScaling` to decision values and their outcomes (true: success) by Newton's
/// method with a backtracking line search on the regularised log-likelihood (Platt 1999,
/// with the numerically safe form of Lin, Lin and Weng 2007). Throws antipode::Error when
/// the lengths differ, a value is not finite, or the examples lack either outcome.
PlattScaling fit_platt_scaling(const std::vector<double>& decision_values,
                               const std::vector<bool>& successes);

/// The area under the ROC curve of `scores` against `successes`: the chance that a random
/// success scores above a random failure (ties count half). 0.5 is chance, 1 perfect. Throws
/// antipode::Error when either outcome is missing.
double roc_auc(const std::vector<double>& scores, const std::vector<bool>& successes);

/// One row of a calibration table: examples whose predicted probability falls in one bin.
struct CalibrationBin {
  std::size_t count = 0;   ///< examples in the bin
  double predicted = 0.0;  ///< their mean predicted probability
  double observed = 0.0;   ///< the share of them that succeeded
};

/// The examples ordered by predicted probability and split into `bins` bins of (as near as
/// possible) equal count - deciles for 10; ties stay in input order. Empty bins are left out.
std::vector<CalibrationBin> calibration_table(const std::vector<double>& probabilities,
                                              const std::vector<bool>& successes,
                                              std::size_t bins = 10);

/// Mean over the bins of |predicted - observed|, each bin weighted equally (the calibration
/// error docs/results.md reports); 0 for an empty table.
double calibration_error(const std::vector<CalibrationBin>& table);

}  // namespace antipode
