#include "slab_grid.hpp"

#include <algorithm>
#include <cmath>

namespace antipode::geometry {
namespace {

constexpr double kMaxCells = 4.0e6;

}  // namespace

SlabGrid::SlabGrid(const std::vector<Eigen::Vector3f>& points, float cell_m) : points_(points) {
  if (points.empty()) {
    start_.assign(2, 0);
    return;
  }
  Eigen::Vector3f lo = points.front(), hi = lo;
  for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Eigen::Vector3f extent = hi - lo;
  cell_ = cell_m;
  auto cells = [&] {
    const Eigen::Array3d n = (extent / cell_).cast<double>().array().floor() + 1.0;
    return n.prod();
  };
  while (cells() > kMaxCells) cell_ *= 2.0f;
  origin_ = lo;
  dims_ = ((extent / cell_).array().floor() + 1.0f).cast<int>();
  std::vector<std::uint32_t> cell(points.size());
  start_.assign(static_cast<std::size_t>(dims_.prod()) + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3i c =
        ((points[i] - origin_) / cell_).array().floor().cast<int>().min(dims_.array() - 1);
    cell[i] = static_cast<std::uint32_t>(cell_of(c));
    ++start_[cell[i] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  order_.resize(points.size());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    order_[next[cell[i]]++] = static_cast<std::int32_t>(i);
  }
}

void SlabGrid::query(const Eigen::Vector3f& centre, const Eigen::Vector3f& axis,
                     float half_thickness_m, float radius_m, std::vector<std::int32_t>& out) const {
  out.clear();
  if (order_.empty()) return;
  const Eigen::Vector3i lo =
      ((centre.array() - radius_m - origin_.array()) / cell_).floor().cast<int>().max(0);
  const Eigen::Vector3i hi = ((centre.array() + radius_m - origin_.array()) / cell_)
                                 .floor()
                                 .cast<int>()
                                 .min(dims_.array() - 1);
  const float half_diagonal = 0.5f * std::sqrt(3.0f) * cell_;
  const float cell_slab = half_thickness_m + half_diagonal;
  const float cell_ball = (radius_m + half_diagonal) * (radius_m + half_diagonal);
  // The innermost loop runs along the axis the slab's normal is most aligned with, over just
  // the cells whose centres can be near the slab.
  Eigen::Index k = 0;
  axis.cwiseAbs().maxCoeff(&k);
  const int i = (static_cast<int>(k) + 1) % 3, j = (static_cast<int>(k) + 2) % 3;
  const Eigen::Vector3f first_middle = origin_ + cell_ * Eigen::Vector3f::Constant(0.5f) - centre;
  Eigen::Vector3i c;
  for (c[i] = lo[i]; c[i] <= hi[i]; ++c[i]) {
    for (c[j] = lo[j]; c[j] <= hi[j]; ++c[j]) {
      // Cell centres along k: first_middle[k] + cell * n; the slab needs
      // |axis[k] * (first_middle[k] + cell * n) + across| <= cell_slab.
      const float across =
          axis[i] * (first_middle[i] + cell_ * c[i]) + axis[j] * (first_middle[j] + cell_ * c[j]);
      const float a = axis[k] * cell_;
      float n0 = (-cell_slab - across - axis[k] * first_middle[k]) / a;
      float n1 = (cell_slab - across - axis[k] * first_middle[k]) / a;
      if (n0 > n1) std::swap(n0, n1);
      const int from = std::max(lo[k], static_cast<int>(std::ceil(n0)));
      const int to = std::min(hi[k], static_cast<int>(std::floor(n1)));
      for (c[k] = from; c[k] <= to; ++c[k]) {
        const Eigen::Vector3f d = first_middle + cell_ * c.cast<float>();
        if (d.squaredNorm() > cell_ball) continue;
        collect(cell_of(c), centre, axis, half_thickness_m, radius_m * radius_m, out);
      }
    }
  }
}

void SlabGrid::collect(std::size_t cell, const Eigen::Vector3f& centre, const Eigen::Vector3f& axis,
                       float half_thickness_m, float squared_radius,
                       std::vector<std::int32_t>& out) const {
  // Every point is written; the end advances only for those inside (branch-free).
  std::size_t end = out.size();
  out.resize(end + (start_[cell + 1] - start_[cell]));
  for (std::uint32_t e = start_[cell]; e < start_[cell + 1]; ++e) {
    const std::int32_t index = order_[e];
    const Eigen::Vector3f q = points_[static_cast<std::size_t>(index)] - centre;
    out[end] = index;
    end += static_cast<std::size_t>((std::abs(q.dot(axis)) <= half_thickness_m) &
                                    (q.squaredNorm() <= squared_radius));
  }
  out.resize(end);
}

}  // namespace antipode::geometry
