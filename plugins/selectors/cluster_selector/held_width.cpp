#include "held_width.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace antipode::selectors {
namespace {

constexpr double kStepRad = 2.0 * M_PI / 180.0;
constexpr double kMinShrinkM = 0.0005;

// The closing direction turned by `about_approach_rad` about the approach axis, then by
// `about_axis_rad` about the hand axis.
Eigen::Vector3f turned_closing(const Hand& hand, double about_approach_rad, double about_axis_rad) {
  const Eigen::Vector3d in_plane =
      std::cos(about_approach_rad) * hand.closing() + std::sin(about_approach_rad) * hand.axis();
  return (std::cos(about_axis_rad) * in_plane + std::sin(about_axis_rad) * hand.approach())
      .cast<float>();
}

}  // namespace

double trimmed_extent_m(const Hand& hand, const Cloud& cloud, const Eigen::Vector3f& direction,
                        double trim, std::vector<float>& along) {
  along.clear();
  for (const std::int32_t i : hand.closing_points) {
    along.push_back(cloud.points_m[static_cast<std::size_t>(i)].dot(direction));
  }
  const auto [min, max] = std::minmax_element(along.begin(), along.end());
  const double full = static_cast<double>(*max - *min);
  const auto last = static_cast<double>(along.size() - 1);
  const auto lo = static_cast<std::ptrdiff_t>(std::floor(trim * last));
  const auto hi = static_cast<std::ptrdiff_t>(std::ceil((1.0 - trim) * last));
  std::nth_element(along.begin(), along.begin() + lo, along.end());
  const float low = along[static_cast<std::size_t>(lo)];
  // Everything after position lo is now at least `low`: the hi-th value is among them.
  if (hi > lo) std::nth_element(along.begin() + lo + 1, along.begin() + hi, along.end());
  const double bulk = static_cast<double>(along[static_cast<std::size_t>(hi)] - low);
  return std::min(full, bulk / (1.0 - 2.0 * trim));
}

double held_width_m(const Hand& hand, const Cloud& cloud, double trim, double max_turn_deg,
                    std::vector<float>& scratch) {
  if (hand.closing_points.empty()) return hand.width_m;
  const int max_steps = static_cast<int>(std::floor(max_turn_deg * M_PI / 180.0 / kStepRad));
  const auto width_at = [&](int a, int b) {
    return trimmed_extent_m(hand, cloud, turned_closing(hand, a * kStepRad, b * kStepRad), trim,
                            scratch);
  };
  // Steepest descent over the grid of turns, one step about either axis at a time. The turn
  // just left is never measured again: it is the one step back, and it was wider.
  int a = 0, b = 0;
  int back_a = 0, back_b = 0;  // the step back to the turn before ({0, 0}, no step, at first)
  double width = width_at(0, 0);
  for (;;) {
    int best_a = a, best_b = b;
    double best = width - kMinShrinkM;
    for (const auto& [da, db] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      if (std::abs(a + da) > max_steps || std::abs(b + db) > max_steps) continue;
      if (da == back_a && db == back_b) continue;
      const double w = width_at(a + da, b + db);
      if (w < best) best = w, best_a = a + da, best_b = b + db;
    }
    if (best_a == a && best_b == b) return width;
    back_a = a - best_a, back_b = b - best_b;
    a = best_a, b = best_b, width = best;
  }
}

}  // namespace antipode::selectors
