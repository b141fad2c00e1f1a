#include "convex_hull.hpp"

#include <algorithm>

namespace antipode::geometry {

std::vector<Eigen::Vector2f> convex_hull(std::vector<Eigen::Vector2f> p) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  const auto turn = [](const Eigen::Vector2f& o, const Eigen::Vector2f& a,
                       const Eigen::Vector2f& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2f> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p[i]) <= 0.0f) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], p[i - 1]) <= 0.0f) --k;
    hull[k++] = p[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace antipode::geometry
