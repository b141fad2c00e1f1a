#include "antipode/grasp/svm_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "antipode/core/random.hpp"
#include "support/error_of.hpp"

namespace antipode {
namespace {

using testing::error_of;

// K(a, b) = a . b: the polynomial kernel of degree 1, gamma 1, coef0 0.
SvmKernel linear(double C) { return SvmKernel{SvmKernelType::kPolynomial, 1, 1.0, 0.0, C}; }

// Two classes of 2-D points around (+1, +1) and (-1, -1), overlapping (sigma 1).
struct Blobs {
  std::vector<float> rows;
  std::vector<std::int8_t> labels;
  std::size_t size() const { return labels.size(); }
};

Blobs blobs(std::size_t n, std::uint64_t seed) {
  RandomStream random(seed);
  Blobs b;
  for (std::size_t i = 0; i < n; ++i) {
    const bool positive = i % 2 == 0;
    const double centre = positive ? 1.0 : -1.0;
    b.rows.push_back(static_cast<float>(centre + random.normal()));
    b.rows.push_back(static_cast<float>(centre + random.normal()));
    b.labels.push_back(positive ? 1 : -1);
  }
  return b;
}

double kernel_value(const SvmKernel& k, const float* a, const float* b) {
  const double dot = double{a[0]} * b[0] + double{a[1]} * b[1];
  if (k.type == SvmKernelType::kRbf) {
    const double dx = double{a[0]} - b[0];
    const double dy = double{a[1]} - b[1];
    return std::exp(-k.gamma * (dx * dx + dy * dy));
  }
  return std::pow(k.gamma * dot + k.coef0, k.degree);
}

// f(x_t) = sum_s y_s a_s K(x_s, x_t) - rho, in double precision.
double decision(const Blobs& b, const SvmDualSolution& s, const SvmKernel& k, std::size_t t) {
  double f = -s.rho;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (s.alpha[i] > 0.0)
      f += b.labels[i] * s.alpha[i] * kernel_value(k, &b.rows[2 * i], &b.rows[2 * t]);
  }
  return f;
}

TEST(SvmSolverTest, TwoPointsGiveTheHardMarginByHand) {
  // x = 3 (grasp) and x = 1 (not): the separating point is 2, w = 1, rho = 2, and
  // w = 3 a_1 - 1 a_2 with a_1 = a_2 gives a = 0.5; objective 1/2 w^2 - sum a = -0.5.
  const std::vector<float> rows = {3.0f, 0.0f, 1.0f, 0.0f};
  const std::vector<std::int8_t> labels = {1, -1};
  const SvmDualSolution s = solve_svm_dual(rows.data(), 2, 2, labels, linear(10.0));
  ASSERT_TRUE(s.converged);
  EXPECT_NEAR(s.alpha[0], 0.5, 1e-9);
  EXPECT_NEAR(s.alpha[1], 0.5, 1e-9);
  EXPECT_NEAR(s.rho, 2.0, 1e-9);
  EXPECT_NEAR(s.objective, -0.5, 1e-9);
  // With C = 0.1 both multipliers stop at C: w = 0.2, objective 0.02 - 0.2.
  const SvmDualSolution soft = solve_svm_dual(rows.data(), 2, 2, labels, linear(0.1));
  EXPECT_EQ(soft.alpha[0], 0.1);
  EXPECT_EQ(soft.alpha[1], 0.1);
  EXPECT_NEAR(soft.objective, -0.18, 1e-9);
}

// The optimality conditions at the solution: y f >= 1 at a = 0, y f = 1 for free
// multipliers, y f <= 1 at a = C_t (C x positive_weight for positive rows), and sum y a = 0.
void expect_optimal(const Blobs& b, const SvmKernel& k, const SvmSolverOptions& options) {
  const SvmDualSolution s = solve_svm_dual(b.rows.data(), b.size(), 2, b.labels, k, options);
  ASSERT_TRUE(s.converged);
  const double slack = 5 * options.tolerance;
  double balance = 0.0;
  std::size_t free = 0;
  std::size_t bounded = 0;
  for (std::size_t t = 0; t < b.size(); ++t) {
    balance += b.labels[t] * s.alpha[t];
    const double margin = b.labels[t] * decision(b, s, k, t);
    const double C_t = b.labels[t] > 0 ? k.C * options.positive_weight : k.C;
    ASSERT_GE(s.alpha[t], 0.0);
    ASSERT_LE(s.alpha[t], C_t);
    if (s.alpha[t] == 0.0) {
      EXPECT_GE(margin, 1.0 - slack) << t;
    } else if (s.alpha[t] == C_t) {
      EXPECT_LE(margin, 1.0 + slack) << t;
      ++bounded;
    } else {
      EXPECT_NEAR(margin, 1.0, slack) << t;
      ++free;
    }
  }
  EXPECT_NEAR(balance, 0.0, 1e-9 * k.C * static_cast<double>(b.size()));
  EXPECT_GT(free, 0u);     // the blobs overlap: some points sit on the margin,
  EXPECT_GT(bounded, 0u);  // others inside it
}

TEST(SvmSolverTest, SolutionsMeetTheOptimalityConditions) {
  const Blobs b = blobs(600, 3);
  SvmSolverOptions options;
  expect_optimal(b, SvmKernel{SvmKernelType::kRbf, 3, 0.5, 1.0, 3.0}, options);
  expect_optimal(b, SvmKernel{SvmKernelType::kPolynomial, 3, 0.5, 1.0, 1.0}, options);
  options.tolerance = 1e-5;
  expect_optimal(b, SvmKernel{SvmKernelType::kRbf, 3, 2.0, 1.0, 10.0}, options);
  options.tolerance = 1e-3;
  options.positive_weight = 3.0;
  expect_optimal(b, SvmKernel{SvmKernelType::kRbf, 3, 0.5, 1.0, 3.0}, options);
  options.positive_weight = 0.25;
  expect_optimal(b, SvmKernel{SvmKernelType::kPolynomial, 3, 0.5, 1.0, 1.0}, options);
}

// Training rows called positive (f >= 0) by the solution of `options`.
std::size_t called_positive(const Blobs& b, const SvmKernel& k, const SvmSolverOptions& options) {
  const SvmDualSolution s = solve_svm_dual(b.rows.data(), b.size(), 2, b.labels, k, options);
  std::size_t count = 0;
  for (std::size_t t = 0; t < b.size(); ++t) count += decision(b, s, k, t) >= 0.0 ? 1 : 0;
  return count;
}

TEST(SvmSolverTest, PositiveWeightMovesTheBoundaryTowardsTheNegatives) {
  // The blobs overlap: a costlier miss of a positive row makes the solution call more rows
  // positive, a cheaper one fewer.
  const Blobs b = blobs(600, 3);
  const SvmKernel k{SvmKernelType::kRbf, 3, 0.5, 1.0, 1.0};
  SvmSolverOptions options;
  const std::size_t even = called_positive(b, k, options);
  options.positive_weight = 4.0;
  const std::size_t heavy = called_positive(b, k, options);
  options.positive_weight = 0.25;
  const std::size_t light = called_positive(b, k, options);
  EXPECT_GT(heavy, even + 20);
  EXPECT_LT(light + 20, even);
}

TEST(SvmSolverTest, SameSolutionForAnyCacheSizeOrThreadCount) {
  const Blobs b = blobs(5000, 4);  // more rows than one block of a kernel row
  const SvmKernel k{SvmKernelType::kRbf, 3, 1.0, 1.0, 1.0};
  SvmSolverOptions options;
  options.threads = 1;
  const SvmDualSolution reference =
      solve_svm_dual(b.rows.data(), b.size(), 2, b.labels, k, options);
  options.cache_mib = 0;  // two rows: almost every row is recomputed
  options.threads = 2;
  const SvmDualSolution small = solve_svm_dual(b.rows.data(), b.size(), 2, b.labels, k, options);
  EXPECT_EQ(small.alpha, reference.alpha);
  EXPECT_EQ(small.rho, reference.rho);
  EXPECT_EQ(small.iterations, reference.iterations);
}

TEST(SvmSolverTest, IterationCapStopsWithoutConverging) {
  const Blobs b = blobs(200, 5);
  SvmSolverOptions options;
  options.max_iterations = 3;
  const SvmDualSolution s =
      solve_svm_dual(b.rows.data(), b.size(), 2, b.labels, linear(1.0), options);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations, 3);
  const auto moved =
      std::count_if(s.alpha.begin(), s.alpha.end(), [](double a) { return a > 0.0; });
  EXPECT_GE(moved, 2);  // each update moves two multipliers
  EXPECT_LE(moved, 6);
}

TEST(SvmSolverTest, BadProblemsAreClearErrors) {
  const Blobs b = blobs(10, 6);
  const auto solve = [&](const std::vector<std::int8_t>& labels, double C,
                         const SvmSolverOptions& options = {}) {
    return error_of(
        [&] { solve_svm_dual(b.rows.data(), labels.size(), 2, labels, linear(C), options); });
  };
  EXPECT_EQ(solve(std::vector<std::int8_t>(10, 1), 1.0),
            "SVM solver: the labels hold one class only");
  EXPECT_EQ(solve(b.labels, 0.0), "SVM solver: C must be positive");
  EXPECT_EQ(solve({}, 1.0), "SVM solver: no training rows");
  EXPECT_EQ(error_of([&] { solve_svm_dual(b.rows.data(), 9, 2, b.labels, linear(1.0)); }),
            "SVM solver: 10 labels for 9 rows");
  SvmSolverOptions options;
  options.tolerance = 0.0;
  EXPECT_EQ(solve(b.labels, 1.0, options), "SVM solver options: tolerance must be positive");
  options.tolerance = 1e-3;
  options.positive_weight = 0.0;
  EXPECT_EQ(solve(b.labels, 1.0, options), "SVM solver options: positive_weight must be positive");
}

}  // namespace
}  // namespace antipode
