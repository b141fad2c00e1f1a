#pragma once
// The sensor model's random draws: a small, fast, seeded stream per image row, standard
// normals by the ziggurat method and an arc cosine without the library call. Everything is
// plain arithmetic on 64-bit integers and doubles, so the same seed gives the same numbers on
// every platform and for any number of threads.

#include <cstdint>

namespace antipode::cells {

/// SplitMix64 as a generator: a 64-bit counter passed through a strong mixing function.
class SensorRandom {
 public:
  explicit SensorRandom(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next_u64() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return double(next_u64() >> 11) * 0x1.0p-53; }
  /// Standard normal (ziggurat with 128 layers: one 64-bit draw and a comparison in about
  /// 98.8% of the calls; exact, not an approximation of the normal density).
  double normal();

 private:
  std::uint64_t state_;
};

/// arccos(x) for x in [0, 1], within 1e-7 rad (a polynomial in x times sqrt(1 - x)).
double fast_acos(double x);

}  // namespace antipode::cells
