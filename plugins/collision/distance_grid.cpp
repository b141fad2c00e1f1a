#include "distance_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "antipode/core/error.hpp"
#include "sphere_kernels.hpp"

namespace antipode::collision {

namespace {

// The most cells a grid may have; past it the cells grow (a coarser, still safe grid).
constexpr double kMaxCells = 16e6;

// Along x, per row: the squared distance (in cells) to the nearest occupied cell of the row,
// capped at `cap` - two sweeps, nearest on the left then on the right.
void x_pass(const std::vector<char>& occupied, const Eigen::Vector3i& size, float cap,
            std::vector<float>& d2) {
  const int n = size.x();
  const auto rows = std::size_t(size.y()) * std::size_t(size.z());
  for (std::size_t row = 0; row < rows; ++row) {
    const std::size_t first = row * std::size_t(n);
    int last = -(1 << 20);  // the nearest occupied cell so far
    for (int q = 0; q < n; ++q) {
      if (occupied[first + std::size_t(q)]) last = q;
      const float d = float(q - last);
      d2[first + std::size_t(q)] = std::min(d * d, cap);
    }
    last = 1 << 20;
    for (int q = n - 1; q >= 0; --q) {
      if (occupied[first + std::size_t(q)]) last = q;
      const float d = float(last - q);
      d2[first + std::size_t(q)] = std::min(d2[first + std::size_t(q)], d * d);
    }
  }
}

// Along the axis of `stride` (cells between neighbours): d2 = min over |d| <= reach of
// d^2 + d2 shifted by d, in whole-grid sweeps the kernels vectorize. A shift that runs off a
// row (or a slice) reads the next one's border, which holds no occupied cell within `reach`
// (the grid's padding): it can only lower a value below the truth, never raise it.
void window_pass(std::vector<float>& d2, std::vector<float>& out, std::ptrdiff_t stride,
                 int reach) {
  out = d2;
  const auto n = std::ptrdiff_t(d2.size());
  for (int d = 1; d <= reach; ++d) {
    const std::ptrdiff_t shift = d * stride;
    if (shift >= n) break;
    const auto add = float(d) * float(d);
    min_shifted(out.data(), d2.data(), n - shift, shift, add);                   // from +d
    min_shifted(out.data() + shift, d2.data() + shift, n - shift, -shift, add);  // from -d
  }
  d2.swap(out);
}

}  // namespace

DistanceGrid::DistanceGrid(const std::vector<Eigen::Vector3f>& points_m, double resolution_m,
                           double reach_m) {
  if (!(resolution_m > 0.0 && std::isfinite(resolution_m) && reach_m > 0.0 &&
        std::isfinite(reach_m)))
    throw Error("distance grid: the resolution and reach must be positive, got " +
                std::to_string(resolution_m) + " and " + std::to_string(reach_m));
  // The occupied cubes, keyed as octomap keys its leaves: floor(coordinate * (1 / resolution)).
  const double per_metre = 1.0 / resolution_m;
  std::vector<Eigen::Vector3i> cubes;
  cubes.reserve(points_m.size());
  for (const Eigen::Vector3f& p : points_m) {
    const Eigen::Array3d key = (p.cast<double>() * per_metre).array().floor();
    // octomap skips points beyond its keys' range ([-2^15, 2^15) leaves), and so does this.
    if (key.allFinite() && (key >= -32768.0).all() && (key < 32768.0).all())
      cubes.push_back(key.cast<int>());
  }
  if (cubes.empty()) return;
  Eigen::Vector3i lo = cubes.front(), hi = cubes.front();
  for (const Eigen::Vector3i& c : cubes) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  box_min_ = (lo.cast<double>() * resolution_m).cast<float>();
  box_max_ = ((hi + Eigen::Vector3i::Ones()).cast<double>() * resolution_m).cast<float>();
  // Cells of one cube (octomap's leaves), or of 2^k cubes when that would make too many,
  // with a border of more than `reach` on every side. Integer arithmetic from the cubes'
  // indices: a cell boundary computed in floating point could split a cube.
  int per_cell = 1;  // cubes along a cell's edge
  int reach = 0;
  const auto cell_of = [&per_cell](const Eigen::Vector3i& cube) {
    Eigen::Vector3i c;
    for (int a = 0; a < 3; ++a)
      c[a] = cube[a] >= 0 ? cube[a] / per_cell : -((-cube[a] + per_cell - 1) / per_cell);
    return c;
  };
  for (;;) {
    reach = int(std::ceil(reach_m / (resolution_m * per_cell)));
    const Eigen::Vector3i pad = Eigen::Vector3i::Constant(reach + 2);
    origin_ = cell_of(lo) - pad;
    size_ = cell_of(hi) + pad + Eigen::Vector3i::Ones() - origin_;
    if (size_.cast<double>().prod() <= kMaxCells) break;
    per_cell *= 2;
  }
  h_ = float(resolution_m * per_cell);
  std::vector<char> occupied(std::size_t(size_.prod()), 0);
  for (const Eigen::Vector3i& cube : cubes) {
    const Eigen::Vector3i i = cell_of(cube) - origin_;
    occupied[(std::size_t(i.z()) * size_.y() + std::size_t(i.y())) * size_.x() +
             std::size_t(i.x())] = 1;
  }
  // Squared distances in cells between centres, exact up to `reach` cells: along x, then y,
  // then z (the transform is separable); anything farther counts as `reach` + 1.
  const float cap = float(reach + 1) * float(reach + 1);
  std::vector<float> d2(occupied.size()), scratch;
  x_pass(occupied, size_, cap, d2);
  window_pass(d2, scratch, size_.x(), reach);
  window_pass(d2, scratch, std::ptrdiff_t(size_.x()) * size_.y(), reach);
  // sqrt(3) h, and 0.1 mm for the float rounding of the centres the kernels place.
  const float margin = std::sqrt(3.0f) * h_ + 1e-4f;
  clear_m_.resize(d2.size());
  for (std::size_t i = 0; i < d2.size(); ++i)
    clear_m_[i] = std::sqrt(std::min(d2[i], cap)) * h_ - margin;
}

KernelGrid DistanceGrid::kernel() const {
  KernelGrid k{};
  k.clear_m = clear_m_.data();
  k.inv_h = 1.0f / h_;
  for (int a = 0; a < 3; ++a) {
    k.size[a] = size_[a];
    k.origin_f[a] = float(origin_[a]);
    k.size_f[a] = float(size_[a]);
    k.box_min[a] = box_min_[a];
    k.box_max[a] = box_max_[a];
  }
  return k;
}

void DistanceGrid::mark_touching(const float* x, const float* y, const float* z, const float* r,
                                 int n, std::uint8_t* touches) const {
  if (empty()) {
    std::fill(touches, touches + n, std::uint8_t(0));
    return;
  }
  mark_near_points(kernel(), x, y, z, r, n, touches);
}

}  // namespace antipode::collision
