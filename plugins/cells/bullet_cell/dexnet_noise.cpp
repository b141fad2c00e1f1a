#include "dexnet_noise.hpp"

#include <algorithm>
#include <cmath>

#include "sensor_random.hpp"

namespace antipode::cells {
namespace {

// Gamma(shape, 1 / shape): mean 1, standard deviation 1 / sqrt(shape), by Marsaglia and
// Tsang's method (shape >= 1): exact, about 1.02 normal draws per sample.
double unit_mean_gamma(double shape, SensorRandom& random) {
  const double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
  for (;;) {
    const double x = random.normal(), t = 1.0 + c * x;
    if (t <= 0.0) continue;
    const double v = t * t * t, u = random.uniform();
    if (u > 0.0 && std::log(u) < 0.5 * x * x + d - d * v + d * std::log(v)) return d * v / shape;
  }
}

}  // namespace

DexNetNoise::DexNetNoise(const SensorModel& sensor, int width_px, int height_px,
                         std::uint64_t seed) {
  if (sensor.scale <= 0.0) return;
  SensorRandom random(seed);
  // The gain's deviation scales with `scale`: the shape with its inverse square.
  gain_ =
      unit_mean_gamma(std::max(1.0, sensor.gamma_shape / (sensor.scale * sensor.scale)), random);
  cell_px_ = std::max(1, sensor.field_cell_px);
  columns_ = width_px / cell_px_ + 2;
  rows_ = height_px / cell_px_ + 2;
  field_m_.resize(std::size_t(columns_) * std::size_t(rows_));
  for (double& value : field_m_) value = sensor.scale * sensor.field_sigma_m * random.normal();
}

double DexNetNoise::apply(double z_m, int u, int v) const {
  if (field_m_.empty()) return z_m;
  const double gu = double(u) / cell_px_, gv = double(v) / cell_px_;
  const int c = std::min(int(gu), columns_ - 2), r = std::min(int(gv), rows_ - 2);
  const double fu = gu - c, fv = gv - r;
  const auto at = [&](int row, int column) {
    return field_m_[std::size_t(row) * std::size_t(columns_) + std::size_t(column)];
  };
  const double field = (1 - fv) * ((1 - fu) * at(r, c) + fu * at(r, c + 1)) +
                       fv * ((1 - fu) * at(r + 1, c) + fu * at(r + 1, c + 1));
  return z_m * gain_ + field;
}

}  // namespace antipode::cells
