#pragma once
// The depth sensor's error model (PrimeSense / Kinect v1, Nguyen, Izadi & Lovell 2012):
// axial noise growing with depth and at grazing angles, lateral noise in pixels, and
// dropout of returns at grazing angles. `scale` multiplies every effect: 0 = ideal sensor.

namespace antipode::cells {

struct SensorModel {
  double scale = 1.0;
  /// Returns at incidence angles above this are dropped with certainty (rad, ~84 deg) ...
  double dropout_angle_rad = 1.47;
  /// ... and from this angle on they are dropped with rising probability (rad, ~70 deg).
  double dropout_start_rad = 1.22;

  /// Axial standard deviation (m) at depth `z_m` and incidence angle `theta_rad`.
  double axial_sigma_m(double z_m, double theta_rad) const;
  /// Lateral standard deviation in pixels at incidence angle `theta_rad`.
  double lateral_sigma_px(double theta_rad) const;
  /// Probability that a return at `theta_rad` is missing.
  double dropout_probability(double theta_rad) const;
};

}  // namespace antipode::cells
