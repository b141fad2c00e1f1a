// The states a planner's motion is checked at: the rake order is a permutation whose first
// batch is spread along the motion and ends at its last state, and the states are bit for bit
// the motion's, ends as asked.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "segment_states.hpp"

namespace antipode::planning {
namespace {

TEST(RakeOrder, IsAPermutationOfTheStates) {
  for (std::size_t lanes : {0, 1, 2, 3, 7, 16, 40}) {
    for (std::size_t steps = 0; steps <= 100; ++steps) {
      std::vector<std::size_t> order = rake_order(steps, lanes);
      ASSERT_EQ(order.size(), steps) << "lanes " << lanes;
      std::sort(order.begin(), order.end());
      for (std::size_t i = 0; i < steps; ++i) ASSERT_EQ(order[i], i) << "lanes " << lanes;
    }
  }
}

TEST(RakeOrder, ZeroOrOneLaneOrAtLeastAsManyAsStatesKeepTheOrder) {
  for (std::size_t lanes : {0, 1, 10, 11}) {
    const std::vector<std::size_t> order = rake_order(10, lanes);
    ASSERT_EQ(order.size(), 10u);
    for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i) << "lanes " << lanes;
  }
}

TEST(RakeOrder, TheFirstBatchIsEachToothsLastState) {
  const std::vector<std::size_t> even = rake_order(64, 16);  // teeth of 4
  for (std::size_t k = 0; k < 16; ++k) EXPECT_EQ(even[k], 4 * k + 3);
  for (std::size_t k = 0; k < 16; ++k) EXPECT_EQ(even[16 + k], 4 * k + 2);
  // 100 states in 16 teeth of 6 or 7 (tooth t from 100 t / 16).
  const std::vector<std::size_t> uneven = rake_order(100, 16);
  const std::vector<std::size_t> ends = {5,  11, 17, 24, 30, 36, 42, 49,
                                         55, 61, 67, 74, 80, 86, 92, 99};
  EXPECT_EQ(std::vector<std::size_t>(uneven.begin(), uneven.begin() + 16), ends);
}

// Whatever the number of states, the first batch holds the last state (the new state of an
// extension) and meets every stretch of consecutive states as long as the longest tooth,
// ceil(steps / lanes), wherever it lies.
TEST(RakeOrder, TheFirstBatchEndsTheMotionAndMeetsEveryStretchOfATooth) {
  const std::size_t lanes = 16;
  for (std::size_t steps = 1; steps <= 300; ++steps) {
    const std::size_t teeth = std::min(lanes, steps), longest = (steps + teeth - 1) / teeth;
    const std::vector<std::size_t> order = rake_order(steps, lanes);
    const std::vector<std::size_t> batch(order.begin(), order.begin() + std::ptrdiff_t(teeth));
    ASSERT_NE(std::find(batch.begin(), batch.end(), steps - 1), batch.end()) << steps;
    for (std::size_t begin = 0; begin + longest <= steps; ++begin) {
      const bool met = std::any_of(batch.begin(), batch.end(), [&](std::size_t i) {
        return i >= begin && i < begin + longest;
      });
      ASSERT_TRUE(met) << "steps " << steps << ", stretch from " << begin;
    }
  }
}

// The states are the ones OMPL's discrete motion validator checks, bit for bit:
// a + (b - a) * (i / steps).
TEST(SegmentStates, AreTheMotionsStatesBitForBit) {
  Eigen::VectorXd a(7), b(7);
  a << 0.1, -0.55, 0.3, 0.75, -1.2, 1.26, 0.05;
  b << -0.8, -0.3, 0.4, 1.2, -0.3, 0.9, 0.2;
  const double resolution_rad = 0.02;
  const auto steps = std::size_t(std::ceil((b - a).norm() / resolution_rad));
  for (const bool include_start : {false, true}) {
    for (const std::size_t lanes : {0, 16}) {
      std::vector<Eigen::VectorXd> states;
      segment_states(a, b, resolution_rad, include_start, lanes, states);
      const std::size_t first = include_start ? 0 : 1;
      ASSERT_EQ(states.size(), steps + 1 - first);
      const std::vector<std::size_t> order = rake_order(states.size(), lanes);
      for (std::size_t k = 0; k < states.size(); ++k) {
        const Eigen::VectorXd expected =
            a + (b - a) * (double(order[k] + first) / double(steps));  // the validator's formula
        ASSERT_TRUE((states[k].array() == expected.array()).all()) << k;
      }
    }
  }
}

TEST(SegmentStates, HaveTheEndsAsAsked) {
  Eigen::VectorXd a(2), b(2);
  a << 0.0, 0.0;
  b << 0.3, 0.4;  // 0.5 long: 10 steps of 0.05
  std::vector<Eigen::VectorXd> with_start, without_start;
  segment_states(a, b, 0.05, true, 16, with_start);
  segment_states(a, b, 0.05, false, 4, without_start);
  ASSERT_EQ(with_start.size(), 11u);
  ASSERT_EQ(without_start.size(), 10u);
  const auto by_x = [](const Eigen::VectorXd& p, const Eigen::VectorXd& q) { return p(0) < q(0); };
  std::sort(with_start.begin(), with_start.end(), by_x);
  std::sort(without_start.begin(), without_start.end(), by_x);
  EXPECT_EQ(with_start.front(), a);
  EXPECT_EQ(with_start.back(), b);
  EXPECT_GT(without_start.front()(0), 0.0);
  EXPECT_EQ(without_start.back(), b);
  segment_states(a, a, 0.05, false, 16, without_start);  // no motion: one step, to itself
  ASSERT_EQ(without_start.size(), 1u);
  EXPECT_EQ(without_start[0], a);
}

}  // namespace
}  // namespace antipode::planning
