#pragma once
/// @file
/// Seeded random streams. Every random draw in antipode comes from a RandomStream derived
/// from the run's seed, so results are reproducible and independent of the thread count:
/// parallel loops derive one stream per work item (`stream.derive(item_index)`), never one
/// per thread.

#include <cstdint>
#include <random>

namespace antipode {

/// A deterministic pseudo-random stream (64-bit Mersenne Twister seeded through SplitMix64).
///
/// The distributions are implemented here rather than with <random>'s, whose algorithms the
/// C++ standard leaves to each library: the same seed must give the same numbers everywhere.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed = 0);

  /// An independent child stream for work item `index`; the same (seed, index) always gives
  /// the same child, whatever was drawn from this stream before.
  RandomStream derive(std::uint64_t index) const;

  std::uint64_t seed() const { return seed_; }
  std::uint64_t next_u64() { return engine_(); }
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n); n must be > 0.
  std::uint64_t below(std::uint64_t n);
  /// Standard normal (Box-Muller, no cached second value so draws stay order-independent).
  double normal();

 private:
  std::uint64_t seed_;
  std::mt19937_64 engine_;
};

/// SplitMix64 finaliser: a well-mixed 64-bit hash used to derive seeds.
std::uint64_t mix_seed(std::uint64_t value);

}  // namespace antipode
