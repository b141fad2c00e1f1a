#include "antipode/grasp/svm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "antipode/core/error.hpp"
#include "kernel_rows.hpp"

namespace antipode {
namespace {

// Curvature used when a pair's second-order term is not positive (libsvm's tau).
constexpr double kTinyCurvature = 1e-12;
// Pair updates between two shrinking passes (at most the number of rows).
constexpr std::int64_t kShrinkInterval = 1000;

// The solver's state: multipliers a_t, labels y_t and the gradient G_t of the objective,
// G = Q a - 1 with Q_st = y_s y_t K_st. Multiplier s can move up (if y_s > 0) or down (if
// y_s < 0) while it is "up-movable"; t can make the opposite move while it is
// "down-movable". A pair (s, t) moves a_s by y_s lambda and a_t by -y_t lambda (lambda > 0),
// which keeps sum y a = 0. With v_t = -y_t G_t, the solution is optimal when no up-movable
// v exceeds a down-movable v by the tolerance.
//
// Shrinking (as libsvm): multipliers at a bound whose v says they would only move further
// into it leave the active set, so the passes over the rows become shorter. Their gradient is
// rebuilt (from the bound part kept in `at_C_gradient_` and the free multipliers' rows) before
// the final optimality check, and once when the violation first falls below ten tolerances.
class DualProblem {
 public:
  DualProblem(detail::KernelRows& kernel, const std::vector<std::int8_t>& labels, double C_positive,
              double C_negative, double tolerance);

  // Runs pair updates until optimal (true) or `max_iterations` were made (false).
  bool solve(std::int64_t max_iterations, std::int64_t& iterations);
  double rho() const;
  double objective() const;
  std::vector<double> take_alpha() { return std::move(alpha_); }

 private:
  struct Violation {
    double top = -std::numeric_limits<double>::infinity();     // max v, up-movable
    double bottom = -std::numeric_limits<double>::infinity();  // max -v, down-movable
  };

  // The upper bound of a_t: C for the row's class.
  double C(std::size_t t) const { return y_[t] > 0 ? C_positive_ : C_negative_; }
  bool up_movable(std::size_t t) const { return y_[t] > 0 ? alpha_[t] < C(t) : alpha_[t] > 0.0; }
  bool down_movable(std::size_t t) const { return y_[t] > 0 ? alpha_[t] > 0.0 : alpha_[t] < C(t); }
  bool at_C(std::size_t t) const { return alpha_[t] >= C(t); }
  // The headroom of s's move (up-movable) and of t's (down-movable), in units of lambda.
  double up_room(std::size_t s) const { return y_[s] > 0 ? C(s) - alpha_[s] : alpha_[s]; }
  double down_room(std::size_t t) const { return y_[t] > 0 ? alpha_[t] : C(t) - alpha_[t]; }
  double v(std::size_t t) const { return -y_[t] * gradient_[t]; }

  bool select(std::size_t& s, std::size_t& t);
  void move(std::size_t s, std::size_t t);
  void track_bound(std::size_t s, bool was_at_C, const float* K_s);
  Violation violation() const;
  void shrink();
  void reconstruct_gradient();
  void activate_all();

  detail::KernelRows& kernel_;
  double C_positive_;
  double C_negative_;
  double tolerance_;
  std::size_t n_;
  std::vector<int> y_;
  std::vector<double> alpha_;
  std::vector<double> gradient_;
  std::vector<double> at_C_gradient_;  // sum over a_t = C_t of C_t Q_ut: G's part from bounds
  std::vector<std::size_t> active_;
  bool unshrunk_ = false;
};

DualProblem::DualProblem(detail::KernelRows& kernel, const std::vector<std::int8_t>& labels,
                         double C_positive, double C_negative, double tolerance)
    : kernel_(kernel),
      C_positive_(C_positive),
      C_negative_(C_negative),
      tolerance_(tolerance),
      n_(kernel.size()),
      alpha_(n_, 0.0),
      gradient_(n_, -1.0),
      at_C_gradient_(n_, 0.0) {
  y_.reserve(n_);
  for (std::size_t t = 0; t < n_; ++t) y_.push_back(labels[t] > 0 ? 1 : -1);
  activate_all();
}

bool DualProblem::solve(std::int64_t max_iterations, std::int64_t& iterations) {
  const std::int64_t interval =
      std::min<std::int64_t>(kShrinkInterval, static_cast<std::int64_t>(n_));
  std::int64_t until_shrink = interval;
  bool optimal = false;
  for (iterations = 0; iterations < max_iterations; ++iterations) {
    if (--until_shrink == 0) {
      shrink();
      until_shrink = interval;
    }
    std::size_t s = 0;
    std::size_t t = 0;
    if (!select(s, t)) {
      if (active_.size() == n_) {
        optimal = true;
        break;
      }
      reconstruct_gradient();  // optimal on the active set: check all the rows
      activate_all();
      if (!select(s, t)) {
        optimal = true;
        break;
      }
      until_shrink = 1;
    }
    move(s, t);
  }
  if (active_.size() < n_) {
    reconstruct_gradient();
    activate_all();
  }
  return optimal;
}

// s: the most violating up-movable multiplier (first-order choice); t: the down-movable
// partner whose pair gains most by the second-order model, gain = b^2 / curvature with
// b = v_s - v_t. False when the largest violation is below the tolerance.
bool DualProblem::select(std::size_t& s, std::size_t& t) {
  double top = -std::numeric_limits<double>::infinity();
  s = n_;
  for (const std::size_t u : active_) {
    if (v(u) > top && up_movable(u)) {
      top = v(u);
      s = u;
    }
  }
  if (s == n_) return false;
  const float* K_s = kernel_.row(s);
  const double K_ss = kernel_.diagonal(s);
  double bottom = -std::numeric_limits<double>::infinity();
  double best_gain = 0.0;
  t = n_;
  for (const std::size_t u : active_) {
    if (!down_movable(u)) continue;
    bottom = std::max(bottom, -v(u));
    const double b = top - v(u);
    if (b <= 0.0) continue;
    double curvature = K_ss + kernel_.diagonal(u) - 2.0 * K_s[u];
    if (curvature <= 0.0) curvature = kTinyCurvature;
    const double gain = b * b / curvature;
    if (gain > best_gain) {
      best_gain = gain;
      t = u;
    }
  }
  return top + bottom >= tolerance_ && t != n_;
}

void DualProblem::move(std::size_t s, std::size_t t) {
  const float* K_s = kernel_.row(s);
  const float* K_t = kernel_.row(t);  // K_s stays valid: one row was asked for since
  double curvature = kernel_.diagonal(s) + kernel_.diagonal(t) - 2.0 * K_s[t];
  if (curvature <= 0.0) curvature = kTinyCurvature;
  const double lambda = std::min({(v(s) - v(t)) / curvature, up_room(s), down_room(t)});
  const bool s_was_at_C = at_C(s);
  const bool t_was_at_C = at_C(t);
  // Land exactly on a bound when the step is clipped there.
  const bool s_to_bound = lambda >= up_room(s);
  const bool t_to_bound = lambda >= down_room(t);
  alpha_[s] = s_to_bound ? (y_[s] > 0 ? C(s) : 0.0) : alpha_[s] + y_[s] * lambda;
  alpha_[t] = t_to_bound ? (y_[t] > 0 ? 0.0 : C(t)) : alpha_[t] - y_[t] * lambda;
  // G_u += Q_us y_s lambda - Q_ut y_t lambda = y_u lambda (K_us - K_ut).
  for (const std::size_t u : active_) {
    gradient_[u] += y_[u] * lambda * (static_cast<double>(K_s[u]) - K_t[u]);
  }
  track_bound(s, s_was_at_C, K_s);
  track_bound(t, t_was_at_C, K_t);
}

// Keeps at_C_gradient_ (for every row) when multiplier s reaches or leaves C.
void DualProblem::track_bound(std::size_t s, bool was_at_C, const float* K_s) {
  if (was_at_C == at_C(s)) return;
  const double sign = at_C(s) ? C(s) * y_[s] : -C(s) * y_[s];
  for (std::size_t u = 0; u < n_; ++u) at_C_gradient_[u] += sign * y_[u] * K_s[u];
}

DualProblem::Violation DualProblem::violation() const {
  Violation m;
  for (const std::size_t u : active_) {
    if (up_movable(u)) m.top = std::max(m.top, v(u));
    if (down_movable(u)) m.bottom = std::max(m.bottom, -v(u));
  }
  return m;
}

// A multiplier at a bound that can only move down (up) leaves the active set when its v is
// above every up-movable v (below every down-movable v): no pair would pick it.
void DualProblem::shrink() {
  const Violation m = violation();
  if (!unshrunk_ && m.top + m.bottom <= 10.0 * tolerance_) {
    unshrunk_ = true;
    reconstruct_gradient();
    activate_all();
  }
  std::vector<std::size_t> kept;
  kept.reserve(active_.size());
  for (const std::size_t u : active_) {
    const bool up = up_movable(u);
    const bool down = down_movable(u);
    const bool idle = (down && !up && v(u) > m.top) || (up && !down && -v(u) > m.bottom);
    if (!idle) kept.push_back(u);
  }
  active_ = std::move(kept);
}

// G_u = at_C_gradient_u + sum over free t of a_t Q_ut - 1, for the inactive rows.
void DualProblem::reconstruct_gradient() {
  if (active_.size() == n_) return;
  std::vector<char> active(n_, 0);
  for (const std::size_t u : active_) active[u] = 1;
  std::vector<double> sum(n_, 0.0);
  for (std::size_t t = 0; t < n_; ++t) {
    if (alpha_[t] <= 0.0 || at_C(t)) continue;
    const float* K_t = kernel_.row(t);
    const double weight = alpha_[t] * y_[t];
    for (std::size_t u = 0; u < n_; ++u) {
      if (!active[u]) sum[u] += weight * K_t[u];
    }
  }
  for (std::size_t u = 0; u < n_; ++u) {
    if (!active[u]) gradient_[u] = at_C_gradient_[u] + y_[u] * sum[u] - 1.0;
  }
}

void DualProblem::activate_all() {
  active_.resize(n_);
  std::iota(active_.begin(), active_.end(), std::size_t{0});
}

// For a free multiplier (0 < a_t < C_t) the optimality conditions give rho = y_t G_t: their
// mean; without one, the middle of the interval the bounded ones allow.
double DualProblem::rho() const {
  double sum = 0.0;
  std::size_t free = 0;
  double upper = std::numeric_limits<double>::infinity();
  double lower = -std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < n_; ++t) {
    const double yG = y_[t] * gradient_[t];
    if (alpha_[t] > 0.0 && alpha_[t] < C(t)) {
      sum += yG;
      ++free;
    } else if ((alpha_[t] == 0.0) == (y_[t] > 0)) {
      upper = std::min(upper, yG);
    } else {
      lower = std::max(lower, yG);
    }
  }
  return free > 0 ? sum / static_cast<double>(free) : 0.5 * (upper + lower);
}

// 1/2 a'Qa - 1'a = 1/2 sum a_t (G_t - 1), as G = Qa - 1.
double DualProblem::objective() const {
  double sum = 0.0;
  for (std::size_t t = 0; t < n_; ++t) sum += alpha_[t] * (gradient_[t] - 1.0);
  return 0.5 * sum;
}

void check_problem(std::size_t n, std::size_t k, const std::vector<std::int8_t>& labels,
                   const SvmKernel& kernel) {
  if (n == 0 || k == 0) throw Error("SVM solver: no training rows");
  if (labels.size() != n) {
    throw Error("SVM solver: " + std::to_string(labels.size()) + " labels for " +
                std::to_string(n) + " rows");
  }
  if (!(kernel.C > 0.0 && std::isfinite(kernel.C))) throw Error("SVM solver: C must be positive");
  const auto positives = static_cast<std::size_t>(
      std::count_if(labels.begin(), labels.end(), [](std::int8_t l) { return l > 0; }));
  if (positives == 0 || positives == n) {
    throw Error("SVM solver: the labels hold one class only");
  }
}

}  // namespace

void SvmSolverOptions::validate() const {
  const auto fail = [](const std::string& what) { throw Error("SVM solver options: " + what); };
  if (!(tolerance > 0.0 && std::isfinite(tolerance))) fail("tolerance must be positive");
  if (max_iterations < 1) fail("max_iterations must be at least 1");
  if (threads < 0) fail("threads must be >= 0");
  if (!(positive_weight > 0.0 && std::isfinite(positive_weight))) {
    fail("positive_weight must be positive");
  }
}

SvmDualSolution solve_svm_dual(const float* rows, std::size_t n, std::size_t k,
                               const std::vector<std::int8_t>& labels, const SvmKernel& kernel,
                               const SvmSolverOptions& options) {
  options.validate();
  check_problem(n, k, labels, kernel);
  detail::KernelRows kernel_rows(rows, n, k, kernel, options.cache_mib << 20U, options.threads);
  DualProblem problem(kernel_rows, labels, kernel.C * options.positive_weight, kernel.C,
                      options.tolerance);
  SvmDualSolution solution;
  solution.converged = problem.solve(options.max_iterations, solution.iterations);
  solution.rho = problem.rho();
  solution.objective = problem.objective();
  solution.alpha = problem.take_alpha();
  return solution;
}

}  // namespace antipode
