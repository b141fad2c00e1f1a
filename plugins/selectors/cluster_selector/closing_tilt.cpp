#include "closing_tilt.hpp"

#include <algorithm>
#include <cmath>

namespace antipode::selectors {

double closing_tilt_rad(const Hand& hand, const Eigen::Vector3d& up) {
  return std::asin(std::min(1.0, std::abs(hand.closing().dot(up))));
}

double tilt_penalty(double tilt_rad, double free_rad) {
  return tilt_rad <= free_rad ? 0.0 : (tilt_rad - free_rad) * (tilt_rad - free_rad);
}

}  // namespace antipode::selectors
