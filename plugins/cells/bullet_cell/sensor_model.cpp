#include "sensor_model.hpp"

#include <algorithm>
#include <cmath>

namespace antipode::cells {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

// theta kept below pi/2 so the grazing terms stay finite.
double clamp_angle(double theta) { return std::clamp(theta, 0.0, kHalfPi - 0.02); }

}  // namespace

double SensorModel::axial_sigma_m(double z, double theta) const {
  theta = clamp_angle(theta);
  const double grazing = theta * theta / ((kHalfPi - theta) * (kHalfPi - theta));
  return scale * (0.0012 + 0.0019 * (z - 0.4) * (z - 0.4) + 0.0001 / std::sqrt(z) * grazing);
}

double SensorModel::lateral_sigma_px(double theta) const {
  theta = clamp_angle(theta);
  return scale * (0.8 + 0.035 * theta / (kHalfPi - theta));
}

double SensorModel::dropout_probability(double theta) const {
  if (scale <= 0.0 || theta <= dropout_start_rad) return 0.0;
  if (theta >= dropout_angle_rad) return 1.0;
  return std::min(1.0,
                  scale * (theta - dropout_start_rad) / (dropout_angle_rad - dropout_start_rad));
}

}  // namespace antipode::cells
