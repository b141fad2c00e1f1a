#include "contact_depth.hpp"

#include <algorithm>
#include <limits>

namespace antipode::selectors {

double contact_start_m(const Hand& hand, const Cloud& cloud, double patch_m) {
  if (hand.closing_points.empty()) return 0.0;
  const Eigen::Vector3f origin = hand.position_m().cast<float>();
  const Eigen::Vector3f approach = hand.approach().cast<float>();
  const Eigen::Vector3f closing = hand.closing().cast<float>();
  const auto along = [&](std::int32_t i, const Eigen::Vector3f& direction) {
    return direction.dot(cloud.points_m[static_cast<std::size_t>(i)] - origin);
  };
  // The first contacts: the finger at -y meets the lowest point along +closing first, the
  // finger at +y the highest.
  float lowest = std::numeric_limits<float>::infinity(), highest = -lowest;
  for (const std::int32_t i : hand.closing_points) {
    lowest = std::min(lowest, along(i, closing));
    highest = std::max(highest, along(i, closing));
  }
  const float patch = static_cast<float>(patch_m);
  float start_minus = std::numeric_limits<float>::infinity(), start_plus = start_minus;
  for (const std::int32_t i : hand.closing_points) {
    const float y = along(i, closing), x = along(i, approach);
    if (y <= lowest + patch) start_minus = std::min(start_minus, x);
    if (y >= highest - patch) start_plus = std::min(start_plus, x);
  }
  return static_cast<double>(std::max(start_minus, start_plus));
}

}  // namespace antipode::selectors
