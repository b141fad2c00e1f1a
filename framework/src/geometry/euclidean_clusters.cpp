// Connected components of the graph that joins two members closer than the tolerance, found
// on a grid instead of by a ball query per member.
//
// The grid's cells are cubes of edge 0.57 x the tolerance, so that any two points of one cell
// are less than 0.99 tolerances apart: a cell's members are one component from the start. Two
// cells more than two cells apart along any axis are more than a tolerance apart. So the
// components follow from a union-find over the occupied cells: each cell is joined to every
// occupied cell at most two cells away along each axis (those after it in the cells' order)
// as soon as one pair of their members is closer than the tolerance, and pairs of cells
// already joined are not looked at again.
//
// Distances are measured as nanoflann's leaf test measures them (the squared differences
// summed in single precision in x, y, z order, less than the squared tolerance), so the
// components are the ones region growing with ball queries of radius `tolerance_m` (PCL's
// EuclideanClusterExtraction) finds - up to a distance within a rounding step of the
// tolerance, where the tree's pruning, summed in another order, may skip a point its leaf
// test would take. Region growing over a nanoflann tree, a ball query per table point at a
// 2 cm tolerance, spent most of the scene stage's time on table_mug.pcd (perf: the tree's
// searches half of it); with the grid, and RANSAC's scoring made lean, the scene stage went
// from 24.3 to 11.4 ms (sampling_bench BM_SceneLayout, side by side).
#include "euclidean_clusters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <unordered_map>

#include "antipode/core/error.hpp"

namespace antipode::geometry {
namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return (static_cast<std::size_t>(c[0]) * 73856093u) ^
           (static_cast<std::size_t>(c[1]) * 19349663u) ^
           (static_cast<std::size_t>(c[2]) * 83492791u);  // unsigned: wraps, never overflows
  }
};

// The squared distance as nanoflann's L2_Simple_Adaptor computes it.
float squared_distance(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  float sum = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float d = a[i] - b[i];
    sum += d * d;
  }
  return sum;
}

// The cell holding `p`, if it has one.
std::optional<Cell> cell_at(const Eigen::Vector3f& p, float edge_m) {
  constexpr double kMaxCell = 1e15;  // far inside std::int64_t, with room for the offsets
  Cell cell{};
  for (int i = 0; i < 3; ++i) {
    const double at = std::floor(double(p[i]) / double(edge_m));
    if (!(std::fabs(at) < kMaxCell)) return std::nullopt;
    cell[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(at);
  }
  return cell;
}

// Union-find over cells, joining the later root under the earlier.
class Components {
 public:
  explicit Components(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t root(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) {
    a = root(a), b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::size_t> parent_;
};

// Whether any point of `a` is closer than sqrt(limit) to any point of `b`.
bool any_pair_closer(const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& a,
                     const std::vector<std::int32_t>& b, float limit) {
  for (const std::int32_t i : a)
    for (const std::int32_t j : b)
      if (squared_distance(points[std::size_t(i)], points[std::size_t(j)]) < limit) return true;
  return false;
}

}  // namespace

std::vector<std::vector<std::int32_t>> euclidean_clusters(
    const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& members,
    float tolerance_m) {
  if (!(tolerance_m >= 1e-15f && tolerance_m <= 1e15f))
    throw Error("euclidean_clusters: tolerance_m must be in [1e-15, 1e15] m, got " +
                std::to_string(tolerance_m));
  std::vector<std::int32_t> sorted = members;
  std::sort(sorted.begin(), sorted.end());
  const float limit = tolerance_m * tolerance_m;  // as PointIndex::radius_search squares it
  const float edge_m = 0.57f * tolerance_m;       // 0.57 sqrt(3) < 0.99

  // The occupied cells in the order of their first member, and each cell's members. A
  // member without a cell (not finite, or too far out to number its cell) has a cell of its
  // own that no other joins.
  std::unordered_map<Cell, std::size_t, CellHash> cell_of;
  std::vector<std::optional<Cell>> cells;
  std::vector<std::vector<std::int32_t>> in_cell;
  std::vector<std::size_t> cell_of_member(sorted.size());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const std::optional<Cell> c = cell_at(points[std::size_t(sorted[k])], edge_m);
    std::size_t index = cells.size();
    if (c) index = cell_of.emplace(*c, cells.size()).first->second;
    if (index == cells.size()) cells.push_back(c), in_cell.emplace_back();
    in_cell[index].push_back(sorted[k]);
    cell_of_member[k] = index;
  }

  Components components(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (!cells[c]) continue;
    const Cell& here = *cells[c];
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dz = -2; dz <= 2; ++dz) {
          const auto other = cell_of.find({here[0] + dx, here[1] + dy, here[2] + dz});
          if (other == cell_of.end() || other->second <= c) continue;
          if (components.root(c) == components.root(other->second)) continue;
          if (any_pair_closer(points, in_cell[c], in_cell[other->second], limit))
            components.join(c, other->second);
        }
  }

  // Clusters in the order of their smallest member, each in increasing order.
  std::vector<std::vector<std::int32_t>> clusters;
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> cluster_of_root(cells.size(), kNone);  // roots are cell indices
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    std::size_t& cluster = cluster_of_root[components.root(cell_of_member[k])];
    if (cluster == kNone) cluster = clusters.size(), clusters.emplace_back();
    clusters[cluster].push_back(sorted[k]);
  }
  return clusters;
}

}  // namespace antipode::geometry
