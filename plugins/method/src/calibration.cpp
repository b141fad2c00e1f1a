// Platt scaling and the measures of a probability (antipode/grasp/calibration.hpp). Written
// here because no Debian library exposes it: libsvm fits the same sigmoid only inside its own
// training (sigmoid_train is internal), and the fit is forty lines.
#include "antipode/grasp/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

void check_inputs(const std::vector<double>& values, const std::vector<bool>& successes,
                  const char* what) {
  if (values.size() != successes.size()) {
    throw Error(std::string(what) + ": " + std::to_string(values.size()) + " scores but " +
                std::to_string(successes.size()) + " outcomes");
  }
  for (double v : values) {
    if (!std::isfinite(v)) throw Error(std::string(what) + ": a score is not finite");
  }
  const auto wins = std::count(successes.begin(), successes.end(), true);
  if (wins == 0 || wins == static_cast<long>(successes.size())) {
    throw Error(std::string(what) + ": needs both successes and failures, got " +
                std::to_string(wins) + " successes of " + std::to_string(successes.size()));
  }
}

// log(1 + exp(-|x|)) and friends, arranged so that exp never overflows.
struct Sigmoid {
  double p;  // 1 / (1 + exp(x)): the probability of success for x = a f + b
  double q;  // 1 - p
};

Sigmoid sigmoid(double x) {
  if (x >= 0) {
    const double e = std::exp(-x);
    return {e / (1.0 + e), 1.0 / (1.0 + e)};
  }
  const double e = std::exp(x);
  return {1.0 / (1.0 + e), e / (1.0 + e)};
}

// The negative log-likelihood of targets `t` under a, b.
double loss(const std::vector<double>& f, const std::vector<double>& t, double a, double b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = f[i] * a + b;
    sum +=
        x >= 0 ? t[i] * x + std::log1p(std::exp(-x)) : (t[i] - 1.0) * x + std::log1p(std::exp(x));
  }
  return sum;
}

}  // namespace

double PlattScaling::probability(double decision_value) const {
  return sigmoid(a * decision_value + b).p;
}

std::vector<double> PlattScaling::probabilities(const std::vector<double>& decision_values) const {
  std::vector<double> p;
  p.reserve(decision_values.size());
  for (const double f : decision_values) p.push_back(probability(f));
  return p;
}

PlattScaling fit_platt_scaling(const std::vector<double>& f, const std::vector<bool>& successes) {
  check_inputs(f, successes, "Platt scaling");
  const double wins = static_cast<double>(std::count(successes.begin(), successes.end(), true));
  const double losses = static_cast<double>(f.size()) - wins;
  // Platt's smoothed targets keep the fit finite when the classes separate.
  std::vector<double> t(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    t[i] = successes[i] ? (wins + 1.0) / (wins + 2.0) : 1.0 / (losses + 2.0);
  }
  double a = 0.0, b = std::log((losses + 1.0) / (wins + 1.0));
  double value = loss(f, t, a, b);
  constexpr double kSigma = 1e-12, kMinStep = 1e-10;
  for (int iteration = 0; iteration < 100; ++iteration) {
    double h11 = kSigma, h22 = kSigma, h21 = 0.0, g1 = 0.0, g2 = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const Sigmoid s = sigmoid(f[i] * a + b);
      const double d2 = s.p * s.q, d1 = t[i] - s.p;
      h11 += f[i] * f[i] * d2;
      h22 += d2;
      h21 += f[i] * d2;
      g1 += f[i] * d1;
      g2 += d1;
    }
    if (std::abs(g1) < 1e-5 && std::abs(g2) < 1e-5) break;
    const double det = h11 * h22 - h21 * h21;
    const double da = -(h22 * g1 - h21 * g2) / det, db = -(-h21 * g1 + h11 * g2) / det;
    const double slope = g1 * da + g2 * db;
    double step = 1.0;
    while (step >= kMinStep) {
      const double candidate = loss(f, t, a + step * da, b + step * db);
      if (candidate < value + 1e-4 * step * slope) {
        a += step * da;
        b += step * db;
        value = candidate;
        break;
      }
      step /= 2.0;
    }
    if (step < kMinStep) break;  // no descent left: as good as the numbers allow
  }
  return {a, b, static_cast<std::uint64_t>(f.size())};
}

double roc_auc(const std::vector<double>& scores, const std::vector<bool>& successes) {
  check_inputs(scores, successes, "ROC AUC");
  std::vector<std::size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return scores[x] < scores[y]; });
  // Mann-Whitney: the rank sum of the successes, ties given their mean rank.
  double rank_sum = 0.0, wins = 0.0;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j < order.size() && scores[order[j]] == scores[order[i]]) ++j;
    const double mean_rank = 0.5 * static_cast<double>(i + j + 1);  // ranks i+1 .. j
    for (std::size_t k = i; k < j; ++k) {
      if (!successes[order[k]]) continue;
      rank_sum += mean_rank;
      wins += 1.0;
    }
    i = j;
  }
  const double losses = static_cast<double>(scores.size()) - wins;
  return (rank_sum - wins * (wins + 1.0) / 2.0) / (wins * losses);
}

std::vector<CalibrationBin> calibration_table(const std::vector<double>& probabilities,
                                              const std::vector<bool>& successes,
                                              std::size_t bins) {
  if (probabilities.size() != successes.size() || bins == 0) {
    throw Error("calibration table: " + std::to_string(probabilities.size()) + " probabilities, " +
                std::to_string(successes.size()) + " outcomes and " + std::to_string(bins) +
                " bins");
  }
  std::vector<std::size_t> order(probabilities.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return probabilities[x] < probabilities[y];
  });
  std::vector<CalibrationBin> table;
  const std::size_t n = order.size();
  for (std::size_t bin = 0; bin < bins; ++bin) {
    CalibrationBin row;
    for (std::size_t k = bin * n / bins; k < (bin + 1) * n / bins; ++k) {
      row.predicted += probabilities[order[k]];
      row.observed += successes[order[k]] ? 1.0 : 0.0;
      ++row.count;
    }
    if (row.count == 0) continue;
    row.predicted /= static_cast<double>(row.count);
    row.observed /= static_cast<double>(row.count);
    table.push_back(row);
  }
  return table;
}

double calibration_error(const std::vector<CalibrationBin>& table) {
  if (table.empty()) return 0.0;
  double sum = 0.0;
  for (const CalibrationBin& row : table) sum += std::abs(row.predicted - row.observed);
  return sum / static_cast<double>(table.size());
}

}  // namespace antipode
