#pragma once
// One depth image's draw of Dex-Net's noise model (sensor_model.hpp): a multiplicative Gamma
// gain for the whole image and a smooth additive field.

#include <cstdint>
#include <vector>

#include "sensor_model.hpp"

namespace antipode::cells {

class DexNetNoise {
 public:
  /// Draws the image's gain and field from `seed` (the same seed, the same noise).
  DexNetNoise(const SensorModel& sensor, int width_px, int height_px, std::uint64_t seed);

  /// The depth measured at pixel (u, v) where the true depth is `z_m`.
  double apply(double z_m, int u, int v) const;

  double gain() const { return gain_; }

 private:
  double gain_ = 1.0;
  int cell_px_ = 4, columns_ = 0, rows_ = 0;
  std::vector<double> field_m_;  ///< rows_ x columns_ grid values, row-major
};

}  // namespace antipode::cells
