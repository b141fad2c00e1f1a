#include "bin_walls.hpp"

#include <algorithm>
#include <cmath>

namespace antipode::selectors {
namespace {

// Points filling the axis-aligned box [lo, hi] on a grid no coarser than `step_m`.
void fill_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double step_m,
              std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = std::max(1, int(std::ceil((hi[a] - lo[a]) / step_m)));
  for (int i = 0; i <= n.x(); ++i)
    for (int j = 0; j <= n.y(); ++j)
      for (int k = 0; k <= n.z(); ++k) {
        const Eigen::Vector3d t(double(i) / n.x(), double(j) / n.y(), double(k) / n.z());
        points.push_back(lo + t.cwiseProduct(hi - lo));
      }
}

}  // namespace

std::vector<Eigen::Vector3d> wall_points(const Bin& bin, double step_m) {
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector2d half = bin.inner_size_m / 2;
  const double t = bin.wall_thickness_m, z0 = bin.floor_z_m, z1 = z0 + bin.wall_height_m;
  const Eigen::Vector2d& c = bin.center_m;
  // Two walls across x (at -y and +y, spanning the corners), two across y (at -x and +x).
  for (const double side : {-1.0, 1.0}) {
    const double y = c.y() + side * (half.y() + t / 2);
    fill_box({c.x() - half.x() - t, y - t / 2, z0}, {c.x() + half.x() + t, y + t / 2, z1}, step_m,
             points);
    const double x = c.x() + side * (half.x() + t / 2);
    fill_box({x - t / 2, c.y() - half.y(), z0}, {x + t / 2, c.y() + half.y(), z1}, step_m, points);
  }
  return points;
}

bool reaches_into_wall(const Hand& hand, const HandBody& body,
                       const std::vector<Eigen::Vector3d>& walls) {
  HandBox bounds;
  bounds.min_m = body.palm.min_m.cwiseMin(body.finger_minus_y.min_m);
  bounds.max_m = body.palm.max_m.cwiseMax(body.finger_plus_y.max_m);
  const Eigen::Isometry3d X_HandFrame = hand.X_FrameHand.inverse();
  return std::any_of(walls.begin(), walls.end(),
                     [&](const Eigen::Vector3d& p) { return bounds.contains(X_HandFrame * p); });
}

}  // namespace antipode::selectors
