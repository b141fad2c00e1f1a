// The between-runs interval: it resamples whole runs, so failures that one run holds widen it
// where the same failures spread over every run do not.
#include "antipode/evaluation/run_bootstrap.hpp"

#include <gtest/gtest.h>

namespace antipode::evaluation {
namespace {

TEST(RunBootstrapTest, RunsThatAgreeGiveNoWidth) {
  const std::vector<RunCount> runs(10, RunCount{8, 10});
  const auto [lo, hi] = run_bootstrap_interval(runs);
  EXPECT_DOUBLE_EQ(lo, 0.8);
  EXPECT_DOUBLE_EQ(hi, 0.8);
}

TEST(RunBootstrapTest, FailuresHeldByOneRunWidenTheInterval) {
  std::vector<RunCount> runs(9, RunCount{10, 10});
  runs.push_back({0, 10});  // 90 of 100, every failure in one run
  const auto [lo, hi] = run_bootstrap_interval(runs);
  EXPECT_LT(lo, 0.85);
  EXPECT_LT(lo, 0.9);
  EXPECT_GT(hi, 0.9);
  EXPECT_LE(hi, 1.0);
  EXPECT_GE(lo, 0.0);
  // Deterministic: the same runs give the same interval.
  EXPECT_EQ(run_bootstrap_interval(runs), std::make_pair(lo, hi));
}

TEST(RunBootstrapTest, NoTrialsGiveTheWholeRange) {
  EXPECT_EQ(run_bootstrap_interval({}), std::make_pair(0.0, 1.0));
  EXPECT_EQ(run_bootstrap_interval({{0, 0}, {0, 0}}), std::make_pair(0.0, 1.0));
}

}  // namespace
}  // namespace antipode::evaluation
