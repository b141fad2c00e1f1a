#include "held_width.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace antipode::selectors {

double held_width_m(const Hand& hand, const Cloud& cloud, double trim, std::vector<float>& along) {
  if (hand.closing_points.empty()) return hand.width_m;
  const Eigen::Vector3f closing = hand.closing().cast<float>();
  along.clear();
  for (const std::int32_t i : hand.closing_points) {
    along.push_back(cloud.points_m[static_cast<std::size_t>(i)].dot(closing));
  }
  const auto last = static_cast<double>(along.size() - 1);
  const auto lo = static_cast<std::ptrdiff_t>(std::floor(trim * last));
  const auto hi = static_cast<std::ptrdiff_t>(std::ceil((1.0 - trim) * last));
  std::nth_element(along.begin(), along.begin() + lo, along.end());
  const float low = along[static_cast<std::size_t>(lo)];
  std::nth_element(along.begin(), along.begin() + hi, along.end());
  const double bulk = static_cast<double>(along[static_cast<std::size_t>(hi)] - low);
  return bulk / (1.0 - 2.0 * trim);
}

}  // namespace antipode::selectors
