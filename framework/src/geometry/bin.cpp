#include "antipode/geometry/bin.hpp"

#include <cmath>
#include <string>

namespace antipode {
namespace {

Eigen::Vector2d pair_at(const Parameters& p, const std::string& key) {
  const auto v = p.require<std::vector<double>>(key);
  if (v.size() != 2 || !std::isfinite(v[0]) || !std::isfinite(v[1]))
    p.fail(key, "'" + key + "' needs two numbers [x, y]");
  return {v[0], v[1]};
}

}  // namespace

std::array<Eigen::AlignedBox3d, 4> Bin::walls() const {
  const Eigen::Vector2d half = inner_size_m / 2;
  const double t = wall_thickness_m;
  const double z0 = floor_z_m, z1 = floor_z_m + wall_height_m;
  const Eigen::Vector2d lo = center_m - half, hi = center_m + half;
  using Box = Eigen::AlignedBox3d;
  using V = Eigen::Vector3d;
  return {Box(V(lo.x() - t, lo.y() - t, z0), V(hi.x() + t, lo.y(), z1)),  // -y, corners
          Box(V(lo.x() - t, hi.y(), z0), V(hi.x() + t, hi.y() + t, z1)),  // +y, corners
          Box(V(lo.x() - t, lo.y(), z0), V(lo.x(), hi.y(), z1)),          // -x
          Box(V(hi.x(), lo.y(), z0), V(hi.x() + t, hi.y(), z1))};         // +x
}

std::vector<AxisBox> Bin::fixtures(double inward_m, double outward_m) const {
  std::vector<AxisBox> out;
  const auto all = walls();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Eigen::AlignedBox3d& wall = all[i];
    Eigen::Vector3d lo = wall.min().array() - outward_m, hi = wall.max().array() + outward_m;
    // The face towards the inside, across the wall: walls 0 and 1 (-y, +y) face along y,
    // walls 2 and 3 (-x, +x) along x; the even one lies on the low side.
    const int axis = i < 2 ? 1 : 0;
    if (i % 2 == 0)
      hi[axis] = wall.max()[axis] + inward_m;
    else
      lo[axis] = wall.min()[axis] - inward_m;
    out.push_back({lo.cast<float>(), hi.cast<float>()});
  }
  return out;
}

Bin read_bin(const Parameters& p) {
  Bin bin;
  bin.center_m = pair_at(p, "center_m");
  bin.inner_size_m = pair_at(p, "inner_size_m");
  if (!(bin.inner_size_m.minCoeff() > 0.0 && bin.inner_size_m.maxCoeff() <= 10.0))
    p.fail("inner_size_m", "'inner_size_m' must be in (0, 10] m");
  bin.floor_z_m = p.number_in("floor_z_m", bin.floor_z_m, -1e3, 1e3);
  bin.wall_height_m = p.number_in("wall_height_m", bin.wall_height_m, 0.001, 2.0);
  bin.wall_thickness_m = p.number_in("wall_thickness_m", bin.wall_thickness_m, 0.001, 0.5);
  p.reject_unknown();
  return bin;
}

}  // namespace antipode
