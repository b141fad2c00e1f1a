#include "antipode/core/random.hpp"

#include <cmath>

namespace antipode {

std::uint64_t mix_seed(std::uint64_t value) {
  value += 0x9e3779b97f4a7c15ULL;
  value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ULL;
  value = (value ^ (value >> 27)) * 0x94d049bb133111ebULL;
  return value ^ (value >> 31);
}

RandomStream::RandomStream(std::uint64_t seed) : seed_(seed), engine_(mix_seed(seed)) {}

RandomStream RandomStream::derive(std::uint64_t index) const {
  return RandomStream(mix_seed(seed_ ^ mix_seed(index + 0x632be59bd9b4e019ULL)));
}

double RandomStream::uniform() {
  // 53 random bits -> a double in [0, 1), exactly representable.
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

std::uint64_t RandomStream::below(std::uint64_t n) {
  // Rejection sampling removes the modulo bias.
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  std::uint64_t value = engine_();
  while (value >= limit) value = engine_();
  return value % n;
}

double RandomStream::normal() {
  double u1 = uniform();
  while (u1 <= 0.0) u1 = uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

}  // namespace antipode
