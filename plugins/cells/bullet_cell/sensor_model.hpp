#pragma once
// The depth sensor's error models. PrimeSense / Kinect v1 (Nguyen, Izadi & Lovell 2012):
// axial noise growing with depth and at grazing angles, lateral noise in pixels, and dropout
// of returns at grazing angles. Dex-Net's (Mahler et al. 2017; the noise of GIGA's and VGN's
// noisy clutter benchmarks): each image's depths multiplied by one Gamma draw (shape 1000,
// mean 1: a 3% scale error), plus correlated additive noise - normals of 5 mm on a grid 4
// pixels apart, interpolated bilinearly. `scale` multiplies every effect: 0 = ideal sensor.

#include <cstdint>

namespace antipode::cells {

enum class SensorKind : std::uint8_t { kPrimeSense, kDexNet };

struct SensorModel {
  SensorKind kind = SensorKind::kPrimeSense;
  double scale = 1.0;
  /// Returns at incidence angles above this are dropped with certainty (rad, ~84 deg) ...
  double dropout_angle_rad = 1.47;
  /// ... and from this angle on they are dropped with rising probability (rad, ~70 deg).
  double dropout_start_rad = 1.22;
  double gamma_shape = 1000.0;   ///< Dex-Net: shape of the multiplicative draw (mean 1)
  double field_sigma_m = 0.005;  ///< Dex-Net: standard deviation of the additive field
  int field_cell_px = 4;         ///< Dex-Net: the additive field's grid step

  /// Axial standard deviation (m) at depth `z_m` and incidence angle `theta_rad`.
  double axial_sigma_m(double z_m, double theta_rad) const;
  /// Lateral standard deviation in pixels at incidence angle `theta_rad`.
  double lateral_sigma_px(double theta_rad) const;
  /// Probability that a return at `theta_rad` is missing.
  double dropout_probability(double theta_rad) const;
};

}  // namespace antipode::cells
