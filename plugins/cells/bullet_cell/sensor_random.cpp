#include "sensor_random.hpp"

#include <array>
#include <cmath>

namespace antipode::cells {
namespace {

constexpr int kLayers = 128;
// Start of the tail and the area of every layer for 128 layers (Marsaglia & Tsang 2000).
constexpr double kTailStart = 3.442619855899;
constexpr double kLayerArea = 9.91256303526217e-3;

double density(double x) { return std::exp(-0.5 * x * x); }

// Layer i (1 <= i < kLayers) is the rectangle [0, x[i]] x [f(x[i]), f(x[i + 1])]; layer 0 is
// [0, x[0]] x [0, f(r)], the base strip plus the tail beyond r, with x[0] = area / f(r).
struct Ziggurat {
  std::array<double, kLayers + 1> x;
  std::array<double, kLayers + 1> f;
  Ziggurat() {
    x[0] = kLayerArea / density(kTailStart);
    x[1] = kTailStart;
    for (int i = 1; i + 1 < kLayers; ++i)
      x[i + 1] = std::sqrt(-2.0 * std::log(kLayerArea / x[i] + density(x[i])));
    x[kLayers] = 0.0;
    for (int i = 0; i <= kLayers; ++i) f[i] = density(x[i]);
  }
};

const Ziggurat& ziggurat() {
  static const Ziggurat table;
  return table;
}

}  // namespace

double SensorRandom::normal() {
  const Ziggurat& z = ziggurat();
  for (;;) {
    const std::uint64_t bits = next_u64();
    const int layer = int(bits & (kLayers - 1));
    const double sign = (bits & kLayers) ? -1.0 : 1.0;
    const double u = double(bits >> 11) * 0x1.0p-53;  // independent of the 8 low bits
    const double x = u * z.x[layer];
    if (x < z.x[layer + 1]) return sign * x;
    if (layer == 0) {
      // The tail beyond r (Marsaglia 1964): exponential proposals, accepted under the density.
      for (;;) {
        const double a = -std::log(1.0 - uniform()) / kTailStart;
        const double b = -std::log(1.0 - uniform());
        if (2.0 * b > a * a) return sign * (kTailStart + a);
      }
    }
    // The wedge of layer `layer` beyond x[layer + 1]: accept under the curve.
    const double y = z.f[layer] + uniform() * (z.f[layer + 1] - z.f[layer]);
    if (y < density(x)) return sign * x;
  }
}

double fast_acos(double x) {
  // Abramowitz & Stegun 4.4.46: |error| <= 2e-8 on [0, 1].
  const double p =
      1.5707963050 +
      x * (-0.2145988016 +
           x * (0.0889789874 +
                x * (-0.0501743046 +
                     x * (0.0308918810 +
                          x * (-0.0170881256 + x * (0.0066700901 + x * -0.0012624911))))));
  return std::sqrt(1.0 - x) * p;
}

}  // namespace antipode::cells
