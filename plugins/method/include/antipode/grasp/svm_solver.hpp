#pragma once
/// @file
/// The soft-margin SVM's training problem in its dual form,
///
///   min_a  1/2 sum_s sum_t a_s a_t y_s y_t K(z_s, z_t) - sum_t a_t
///   s.t.   0 <= a_t <= C_t,   sum_t y_t a_t = 0,
///
/// where C_t is C for negative rows and C x positive_weight for positive ones (1 by default),
/// solved by sequential minimal optimisation: each step moves the pair of multipliers that
/// a second-order model of the objective says gains most (Fan, Chen and Lin, "Working set
/// selection using second order information", JMLR 2005), until the largest violation of the
/// optimality conditions is below a tolerance (libsvm's stopping rule). Multipliers held at
/// a bound are set aside while they stay there (shrinking). Kernel rows are computed as one
/// matrix-vector product each and kept in a least-recently-used cache.
///
/// Written here rather than taken from OpenCV or libsvm because both are slower on the
/// classifier's training sets (tens of thousands of short dense rows): OpenCV picks pairs by
/// first-order information only, does not shrink and caps its kernel cache at 500 MB (2.2
/// times as long for the polynomial kernel, 5.2 times for the Gaussian one on 48,000 rows);
/// libsvm stores rows as sparse index-value pairs in double precision (3 to 11 times as long
/// on 5,000-20,000 rows); docs/results.md, "SVM solver". The result is deterministic: it
/// depends on the data and the options only, not on the number of threads computing rows.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "antipode/grasp/svm_model.hpp"

namespace antipode {

struct SvmSolverOptions {
  double tolerance = 1e-3;                 ///< stop when the largest violation is below this
  std::int64_t max_iterations = 10000000;  ///< pair updates before giving up (not an error)
  std::size_t cache_mib = 1024;            ///< kernel row cache (at least two rows are kept)
  int threads = 0;  ///< kernel row workers (0: all); results do not depend on it
  /// The bound of positive rows' multipliers is C x positive_weight, the negative rows' C
  /// (libsvm's -w1): above 1 a missed grasp costs more than a false one.
  double positive_weight = 1.0;

  /// Throws antipode::Error naming the first invalid field.
  void validate() const;
};

/// The solution of the dual problem for `n` rows.
struct SvmDualSolution {
  std::vector<double> alpha;    ///< a_t in [0, C], one per row
  double rho = 0.0;             ///< f(z) = sum_t y_t a_t K(z_t, z) - rho
  double objective = 0.0;       ///< the dual objective at `alpha`
  std::int64_t iterations = 0;  ///< pair updates made
  bool converged = false;       ///< false when max_iterations stopped the solver first
};

/// Solves the dual problem for the `n` rows of `k` numbers at `rows` (row-major) with labels
/// y_t = +1 when labels[t] > 0 and -1 otherwise, for `kernel` (its type, degree, gamma,
/// coef0 and C). Throws antipode::Error when n is 0, k is 0, C is not positive or one class
/// is missing.
SvmDualSolution solve_svm_dual(const float* rows, std::size_t n, std::size_t k,
                               const std::vector<std::int8_t>& labels, const SvmKernel& kernel,
                               const SvmSolverOptions& options = {});

}  // namespace antipode
