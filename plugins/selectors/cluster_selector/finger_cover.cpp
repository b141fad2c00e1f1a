#include "finger_cover.hpp"

#include <algorithm>

#include "held_width.hpp"

namespace antipode::selectors {

double finger_cover(const Hand& hand, const Cloud& cloud, const HandGeometry& geometry, double trim,
                    std::vector<float>& scratch) {
  if (hand.closing_points.empty() || !(geometry.height_m > 0.0)) return 1.0;
  const double span_m = trimmed_extent_m(hand, cloud, hand.axis().cast<float>(), trim, scratch);
  return std::clamp(span_m / geometry.height_m, 0.0, 1.0);
}

}  // namespace antipode::selectors
