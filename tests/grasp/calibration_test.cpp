// Platt scaling and the measures of a probability (antipode/grasp/calibration.hpp): known
// answers on data drawn from a known sigmoid, the ROC area's definition, and clear errors.
#include "antipode/grasp/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "support/error_of.hpp"

namespace antipode {
namespace {
using testing::error_of;

// Decision values uniform in [-4, 4], each a success with probability 1 / (1 + exp(a f + b)).
struct Draws {
  std::vector<double> values;
  std::vector<bool> successes;
};

Draws draw(double a, double b, std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> value(-4.0, 4.0), coin(0.0, 1.0);
  Draws d;
  for (std::size_t i = 0; i < n; ++i) {
    const double f = value(random);
    d.values.push_back(f);
    d.successes.push_back(coin(random) < 1.0 / (1.0 + std::exp(a * f + b)));
  }
  return d;
}

TEST(CalibrationTest, PlattScalingRecoversTheSigmoidTheOutcomesWereDrawnFrom) {
  const Draws d = draw(-1.5, 0.5, 20000, 7);
  const PlattScaling fit = fit_platt_scaling(d.values, d.successes);
  EXPECT_NEAR(fit.a, -1.5, 0.1);
  EXPECT_NEAR(fit.b, 0.5, 0.1);
  EXPECT_EQ(fit.examples, 20000u);
  EXPECT_TRUE(fit.fitted());
  EXPECT_FALSE(PlattScaling{}.fitted());
  // Calibrated on its own kind of data: every decile within a few points.
  std::vector<double> p;
  for (double f : d.values) p.push_back(fit.probability(f));
  const auto table = calibration_table(p, d.successes);
  ASSERT_EQ(table.size(), 10u);
  EXPECT_LT(calibration_error(table), 0.03);
  for (std::size_t i = 1; i < table.size(); ++i)
    EXPECT_GE(table[i].predicted, table[i - 1].predicted);
}

TEST(CalibrationTest, ProbabilityIsFiniteAndMonotoneForExtremeValues) {
  const PlattScaling s{-2.0, 0.0, 1};
  EXPECT_EQ(s.probability(0.0), 0.5);
  EXPECT_DOUBLE_EQ(s.probability(1e6), 1.0);
  EXPECT_DOUBLE_EQ(s.probability(-1e6), 0.0);
  EXPECT_GT(s.probability(1.0), s.probability(0.5));
  EXPECT_EQ(s.probabilities({0.0, 1.0, -1e6}),
            (std::vector<double>{0.5, s.probability(1.0), s.probability(-1e6)}));
}

TEST(CalibrationTest, SeparableOutcomesGiveAFiniteSteepSigmoid) {
  const std::vector<double> f = {-3, -2, -1, 1, 2, 3};
  const std::vector<bool> held = {false, false, false, true, true, true};
  const PlattScaling fit = fit_platt_scaling(f, held);
  EXPECT_TRUE(std::isfinite(fit.a) && std::isfinite(fit.b));
  EXPECT_LT(fit.a, 0.0);
  EXPECT_GT(fit.probability(3.0), 0.7);  // Platt's targets stop short of 1 on six examples
  EXPECT_LT(fit.probability(-3.0), 0.3);
}

TEST(CalibrationTest, RocAreaCountsOrderedPairsAndHalfTies) {
  EXPECT_DOUBLE_EQ(roc_auc({1, 2, 3, 4}, {false, false, true, true}), 1.0);
  EXPECT_DOUBLE_EQ(roc_auc({4, 3, 2, 1}, {false, false, true, true}), 0.0);
  // Two successes scored 2 against failures scored 1, 2 and 3: each wins one pair, ties one
  // (half) and loses one - 3 of 6 pairs.
  EXPECT_DOUBLE_EQ(roc_auc({1, 2, 3, 2, 2}, {false, false, false, true, true}), 0.5);
  EXPECT_DOUBLE_EQ(roc_auc({1, 5, 3}, {false, true, false}), 1.0);
  // Decision values uniform in [-4, 4], successes drawn with P = 1 / (1 + exp(-f)): the area
  // is the integral of P(f) (1 - P(g)) over f > g, normalised: 0.9086.
  const Draws d = draw(-1.0, 0.0, 20000, 3);
  EXPECT_NEAR(roc_auc(d.values, d.successes), 0.9086, 0.01);
}

TEST(CalibrationTest, TableSplitsIntoEqualCountsAndSkipsEmptyBins) {
  const std::vector<double> p = {0.9, 0.1, 0.5, 0.3, 0.7};
  const std::vector<bool> held = {true, false, true, false, true};
  const auto five = calibration_table(p, held, 5);
  ASSERT_EQ(five.size(), 5u);
  EXPECT_DOUBLE_EQ(five[0].predicted, 0.1);
  EXPECT_DOUBLE_EQ(five[0].observed, 0.0);
  EXPECT_DOUBLE_EQ(five[4].predicted, 0.9);
  EXPECT_NEAR(calibration_error(five), (0.1 + 0.3 + 0.5 + 0.3 + 0.1) / 5, 1e-12);
  EXPECT_EQ(calibration_table(p, held, 10).size(), 5u);  // five bins of one, five empty
  EXPECT_EQ(calibration_error({}), 0.0);
}

TEST(CalibrationTest, BadInputIsAClearError) {
  EXPECT_NE(error_of([] {
              fit_platt_scaling({1, 2}, {true});
            }).find("2 scores but 1 outcomes"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              fit_platt_scaling({1, 2}, {true, true});
            }).find("needs both successes and failures, got 2 successes of 2"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              roc_auc({1, NAN}, {true, false});
            }).find("ROC AUC: a score is not finite"),
            std::string::npos);
  EXPECT_NE(error_of([] { calibration_table({0.5}, {true}, 0); }).find("0 bins"),
            std::string::npos);
}

}  // namespace
}  // namespace antipode
