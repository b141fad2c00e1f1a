#include "convex_decomposition.hpp"

#include <LinearMath/btConvexHullComputer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>

namespace antipode::cells {
namespace {

enum Voxel : std::uint8_t { kOutside = 0, kSurface = 1, kInterior = 2 };

// A voxel grid with one empty layer around the mesh, so the outside is connected.
struct Grid {
  Eigen::Vector3d origin;  // the outer corner of voxel (0, 0, 0)
  double h = 0.0;
  Eigen::Vector3i n;

  int size() const { return n.x() * n.y() * n.z(); }
  int index(const Eigen::Vector3i& c) const { return c.x() + n.x() * (c.y() + n.y() * c.z()); }
  Eigen::Vector3i cell(int index) const {
    return {index % n.x(), (index / n.x()) % n.y(), index / (n.x() * n.y())};
  }
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d c = (p - origin) / h;
    return {std::clamp(int(std::floor(c.x())), 0, n.x() - 1),
            std::clamp(int(std::floor(c.y())), 0, n.y() - 1),
            std::clamp(int(std::floor(c.z())), 0, n.z() - 1)};
  }
  bool inside(const Eigen::Vector3i& c) const {
    return (c.array() >= 0).all() && (c.array() < n.array()).all();
  }
  Eigen::Vector3d corner(const Eigen::Vector3i& c) const { return origin + c.cast<double>() * h; }
};

const Eigen::Vector3i kNeighbours[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                        {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

Grid make_grid(const TriangleMesh& mesh, int resolution) {
  const Eigen::AlignedBox3f bounds = mesh.bounds();
  Grid grid;
  grid.h = double(bounds.sizes().maxCoeff()) / resolution;
  grid.origin = bounds.min().cast<double>() - Eigen::Vector3d::Constant(grid.h);
  grid.n = ((bounds.sizes().cast<double>() / grid.h).array().ceil() + 3).cast<int>();
  return grid;
}

// Calls `visit` for points of every triangle of `mesh` on a grid at most `spacing_m` apart
// (its corners included).
template <typename Visit>
void for_each_surface_sample(const TriangleMesh& mesh, double spacing_m, Visit visit) {
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[std::size_t(t[0])].cast<double>();
    const Eigen::Vector3d ab = mesh.vertices[std::size_t(t[1])].cast<double>() - a;
    const Eigen::Vector3d ac = mesh.vertices[std::size_t(t[2])].cast<double>() - a;
    const double longest = std::max({ab.norm(), ac.norm(), (ac - ab).norm()});
    const int steps = std::max(1, int(std::ceil(longest / spacing_m)));
    for (int s = 0; s <= steps; ++s)
      for (int u = 0; u + s <= steps; ++u) visit(a + (s * ab + u * ac) / steps);
  }
}

// Marks every voxel a triangle passes through (sampled at a third of a voxel), floods the
// outside from the grid's corner and calls what the flood did not reach interior.
std::vector<std::uint8_t> voxelise(const TriangleMesh& mesh, const Grid& grid) {
  std::vector<std::uint8_t> state(std::size_t(grid.size()), kInterior);
  for_each_surface_sample(mesh, grid.h / 3, [&](const Eigen::Vector3d& p) {
    state[std::size_t(grid.index(grid.cell_of(p)))] = kSurface;
  });
  std::deque<int> queue{0};
  state[0] = kOutside;
  while (!queue.empty()) {
    const Eigen::Vector3i c = grid.cell(queue.front());
    queue.pop_front();
    for (const auto& step : kNeighbours) {
      const Eigen::Vector3i next = c + step;
      if (!grid.inside(next)) continue;
      std::uint8_t& s = state[std::size_t(grid.index(next))];
      if (s != kInterior) continue;
      s = kOutside;
      queue.push_back(grid.index(next));
    }
  }
  return state;
}

// The volume of the convex hull of `points` (0 when they span no volume), and the hull.
double hull_of(const std::vector<btVector3>& points, btConvexHullComputer& hull) {
  if (points.size() < 4) return 0.0;
  hull.compute(&points[0].x(), int(sizeof(btVector3)), int(points.size()), 0, 0);
  double volume = 0.0;
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const btVector3& a = hull.vertices[first->getSourceVertex()];
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
         e->getTargetVertex() != first->getSourceVertex(); e = e->getNextEdgeOfFace())
      volume += double(a.dot(hull.vertices[e->getSourceVertex()].cross(
                    hull.vertices[e->getTargetVertex()]))) /
                6.0;
  }
  return std::abs(volume);
}

// A set of solid voxels (sorted indices), its hull's volume and how much that exceeds the
// voxels' volume.
struct Piece {
  std::vector<int> voxels;
  double hull_volume = 0.0;
  double concavity = 0.0;
  Eigen::Vector3i lo, hi;  // inclusive voxel bounds
};

class Splitter {
 public:
  explicit Splitter(const Grid& grid) : grid_(grid) {}

  // Hull volume minus voxel volume. The hull of a voxel union is the hull of the end faces of
  // its rows along x, so only those corners are passed to the hull.
  double concavity(const std::vector<int>& voxels, double* hull_volume = nullptr) {
    points_.clear();
    const int nx = grid_.n.x();
    for (std::size_t i = 0; i < voxels.size();) {
      std::size_t j = i;
      while (j + 1 < voxels.size() && voxels[j + 1] / nx == voxels[i] / nx) ++j;
      add_face_corners(grid_.cell(voxels[i]), 0);
      add_face_corners(grid_.cell(voxels[j]), 1);
      i = j + 1;
    }
    const double voxel_volume = double(voxels.size()) * grid_.h * grid_.h * grid_.h;
    const double volume = hull_of(points_, hull_);
    if (hull_volume) *hull_volume = volume;
    return std::max(0.0, volume - voxel_volume);
  }

  Piece make_piece(std::vector<int> voxels) {
    Piece piece;
    std::sort(voxels.begin(), voxels.end());
    piece.voxels = std::move(voxels);
    piece.lo = piece.hi = grid_.cell(piece.voxels.front());
    for (int v : piece.voxels) {
      const Eigen::Vector3i c = grid_.cell(v);
      piece.lo = piece.lo.cwiseMin(c);
      piece.hi = piece.hi.cwiseMax(c);
    }
    piece.concavity = piece.voxels.size() < 8 ? 0.0 : concavity(piece.voxels, &piece.hull_volume);
    return piece;
  }

  // Splits `piece` by the best of three planes per axis; empty when no plane divides it.
  std::vector<std::vector<int>> split(const Piece& piece) {
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> best_left, best_right;
    for (int axis = 0; axis < 3; ++axis) {
      const int extent = piece.hi[axis] - piece.lo[axis] + 1;
      if (extent < 2) continue;
      for (int eighth = 1; eighth <= 7; ++eighth) {
        const int cut = piece.lo[axis] + std::max(1, extent * eighth / 8);
        std::vector<int> left, right;
        for (int v : piece.voxels) (grid_.cell(v)[axis] < cut ? left : right).push_back(v);
        if (left.empty() || right.empty()) continue;
        const double cost = concavity(left) + concavity(right);
        if (cost < best) {
          best = cost;
          best_left = std::move(left);
          best_right = std::move(right);
        }
      }
    }
    if (best_left.empty()) return {};
    std::vector<std::vector<int>> parts = components(best_left);
    for (auto& part : components(best_right)) parts.push_back(std::move(part));
    return parts;
  }

  // The 6-connected parts of `voxels` (sorted).
  std::vector<std::vector<int>> components(const std::vector<int>& voxels) {
    std::vector<std::vector<int>> parts;
    std::vector<char> seen(voxels.size(), 0);
    const auto position = [&voxels](int v) {
      const auto it = std::lower_bound(voxels.begin(), voxels.end(), v);
      return it != voxels.end() && *it == v ? long(it - voxels.begin()) : -1L;
    };
    for (std::size_t start = 0; start < voxels.size(); ++start) {
      if (seen[start]) continue;
      std::vector<int> part{voxels[start]};
      seen[start] = 1;
      for (std::size_t q = 0; q < part.size(); ++q) {
        const Eigen::Vector3i c = grid_.cell(part[q]);
        for (const auto& step : kNeighbours) {
          if (!grid_.inside(c + step)) continue;
          const long at = position(grid_.index(c + step));
          if (at >= 0 && !seen[std::size_t(at)]) {
            seen[std::size_t(at)] = 1;
            part.push_back(voxels[std::size_t(at)]);
          }
        }
      }
      parts.push_back(std::move(part));
    }
    return parts;
  }

 private:
  void add_face_corners(const Eigen::Vector3i& c, int side) {
    for (int corner = 0; corner < 4; ++corner) {
      const Eigen::Vector3d p =
          grid_.corner(c + Eigen::Vector3i(side, corner & 1, (corner >> 1) & 1));
      points_.emplace_back(btScalar(p.x()), btScalar(p.y()), btScalar(p.z()));
    }
  }

  const Grid& grid_;
  std::vector<btVector3> points_;
  btConvexHullComputer hull_;
};

// At most `count` of `points`, spread by farthest-point sampling (from the point farthest
// from their mean): a 3 cm sphere kept at 128 points departs from the full hull by about
// 0.4 mm, and Bullet's contact tests cost time in proportion to a hull's vertices.
std::vector<btVector3> spread_subset(const std::vector<btVector3>& points, std::size_t count) {
  if (points.size() <= count) return points;
  btVector3 mean(0, 0, 0);
  for (const auto& p : points) mean += p;
  mean /= btScalar(points.size());
  std::vector<btScalar> distance(points.size(), std::numeric_limits<btScalar>::infinity());
  std::size_t next = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (points[i].distance2(mean) > points[next].distance2(mean)) next = i;
  std::vector<btVector3> chosen;
  while (chosen.size() < count) {
    chosen.push_back(points[next]);
    std::size_t farthest = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      distance[i] = std::min(distance[i], points[i].distance2(chosen.back()));
      if (distance[i] > distance[farthest]) farthest = i;
    }
    next = farthest;
  }
  return chosen;
}

// The hull of `points` as a mesh, with at most `max_vertices` vertices.
TriangleMesh hull_mesh(const std::vector<btVector3>& points, std::size_t max_vertices) {
  btConvexHullComputer hull;
  TriangleMesh mesh;
  if (hull_of(points, hull) <= 0.0) return mesh;
  if (std::size_t(hull.vertices.size()) > max_vertices) {
    std::vector<btVector3> corners(&hull.vertices[0], &hull.vertices[0] + hull.vertices.size());
    if (hull_of(spread_subset(corners, max_vertices), hull) <= 0.0) return mesh;
  }
  for (int v = 0; v < hull.vertices.size(); ++v)
    mesh.vertices.emplace_back(hull.vertices[v].x(), hull.vertices[v].y(), hull.vertices[v].z());
  for (int f = 0; f < hull.faces.size(); ++f) {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const int a = first->getSourceVertex();
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace();
         e->getTargetVertex() != a; e = e->getNextEdgeOfFace())
      mesh.triangles.emplace_back(a, e->getSourceVertex(), e->getTargetVertex());
  }
  return mesh;
}

// The hull of each piece: the points of the mesh's surface in its voxels (sampled half a
// voxel apart), and the corners of the faces its interior voxels share with another piece's
// interior voxels.
std::vector<TriangleMesh> piece_hulls(const TriangleMesh& mesh, const Grid& grid,
                                      const std::vector<std::uint8_t>& state,
                                      const std::vector<Piece>& pieces, std::size_t max_vertices) {
  std::vector<int> label(std::size_t(grid.size()), -1);
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (int v : pieces[p].voxels) label[std::size_t(v)] = int(p);
  std::vector<std::vector<btVector3>> points(pieces.size());
  for_each_surface_sample(mesh, grid.h / 2, [&](const Eigen::Vector3d& q) {
    const int p = label[std::size_t(grid.index(grid.cell_of(q)))];
    if (p >= 0)
      points[std::size_t(p)].emplace_back(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()));
  });
  for (std::size_t p = 0; p < pieces.size(); ++p)
    for (int v : pieces[p].voxels) {
      if (state[std::size_t(v)] != kInterior) continue;
      const Eigen::Vector3i c = grid.cell(v);
      for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
          Eigen::Vector3i next = c;
          next[axis] += side ? 1 : -1;
          const int u = grid.index(next);
          if (label[std::size_t(u)] == int(p) || label[std::size_t(u)] < 0 ||
              state[std::size_t(u)] != kInterior)
            continue;
          for (int corner = 0; corner < 4; ++corner) {
            Eigen::Vector3i k = c;
            k[axis] += side;
            k[(axis + 1) % 3] += corner & 1;
            k[(axis + 2) % 3] += (corner >> 1) & 1;
            const Eigen::Vector3d q = grid.corner(k);
            points[p].emplace_back(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()));
          }
        }
    }
  std::vector<TriangleMesh> hulls;
  for (const auto& piece_points : points) {
    TriangleMesh hull = hull_mesh(piece_points, max_vertices);
    if (!hull.empty()) hulls.push_back(std::move(hull));
  }
  return hulls;
}

}  // namespace

std::vector<TriangleMesh> convex_decomposition(const TriangleMesh& mesh,
                                               const DecompositionOptions& options) {
  if (mesh.triangles.empty() || !(mesh.bounds().sizes().minCoeff() > 0.0f)) return {};
  const Grid grid = make_grid(mesh, std::max(4, options.resolution));
  const std::vector<std::uint8_t> state = voxelise(mesh, grid);
  std::vector<int> solid;
  for (int v = 0; v < grid.size(); ++v)
    if (state[std::size_t(v)] != kOutside) solid.push_back(v);
  Splitter splitter(grid);
  std::vector<Piece> pieces;
  for (auto& part : splitter.components(solid)) pieces.push_back(splitter.make_piece(part));
  std::vector<btVector3> all;
  for (const auto& v : mesh.vertices) all.emplace_back(v.x(), v.y(), v.z());
  btConvexHullComputer scratch;
  const double floor = options.min_concavity * hull_of(all, scratch);
  // How far a piece is from convex enough (positive: split it).
  const auto excess = [&](const Piece& piece) {
    return piece.concavity - std::max(floor, options.max_concavity * piece.hull_volume);
  };
  while (int(pieces.size()) < options.max_pieces) {
    const auto worst =
        std::max_element(pieces.begin(), pieces.end(), [&](const Piece& a, const Piece& b) {
          return (excess(a) > 0 ? a.concavity : 0.0) < (excess(b) > 0 ? b.concavity : 0.0);
        });
    if (excess(*worst) <= 0) break;
    std::vector<std::vector<int>> parts = splitter.split(*worst);
    if (parts.empty()) {
      worst->concavity = 0.0;
      continue;
    }
    *worst = splitter.make_piece(std::move(parts.front()));
    for (std::size_t i = 1; i < parts.size(); ++i)
      pieces.push_back(splitter.make_piece(std::move(parts[i])));
  }
  return piece_hulls(mesh, grid, state, pieces,
                     std::size_t(std::max(8, options.max_hull_vertices)));
}

}  // namespace antipode::cells
