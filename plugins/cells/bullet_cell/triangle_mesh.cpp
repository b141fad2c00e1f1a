#include "triangle_mesh.hpp"

#include <numeric>

namespace antipode::cells {
namespace {

// Signed volume of the tetrahedron (origin, a, b, c), times 6.
double tetra6(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

double TriangleMesh::volume() const {
  double sum = 0.0;
  for (const auto& t : triangles)
    sum += tetra6(vertices[t[0]].cast<double>(), vertices[t[1]].cast<double>(),
                  vertices[t[2]].cast<double>());
  return sum / 6.0;
}

Eigen::Vector3d TriangleMesh::volume_centroid() const {
  double weight = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& t : triangles) {
    const Eigen::Vector3d a = vertices[t[0]].cast<double>(), b = vertices[t[1]].cast<double>(),
                          c = vertices[t[2]].cast<double>();
    const double w = tetra6(a, b, c);
    weight += w;
    sum += w * (a + b + c) / 4.0;
  }
  if (std::abs(weight) > 1e-15) return sum / weight;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& v : vertices) mean += v.cast<double>();
  return vertices.empty() ? mean : Eigen::Vector3d(mean / double(vertices.size()));
}

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f box;
  for (const auto& v : vertices) box.extend(v);
  return box;
}

void TriangleMesh::transform(const Eigen::Affine3f& transform) {
  for (auto& v : vertices) v = transform * v;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const int offset = static_cast<int>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) triangles.push_back(t + Eigen::Vector3i::Constant(offset));
}

std::vector<TriangleMesh> connected_pieces(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) parent[find_root(parent, t[k])] = find_root(parent, t[0]);
  std::vector<int> piece_of_root(mesh.vertices.size(), -1);
  std::vector<int> local(mesh.vertices.size(), -1);
  std::vector<TriangleMesh> pieces;
  for (const auto& t : mesh.triangles) {
    const int root = find_root(parent, t[0]);
    if (piece_of_root[root] < 0) {
      piece_of_root[root] = static_cast<int>(pieces.size());
      pieces.emplace_back();
    }
    TriangleMesh& piece = pieces[piece_of_root[root]];
    Eigen::Vector3i mapped;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] < 0) {
        local[t[k]] = static_cast<int>(piece.vertices.size());
        piece.vertices.push_back(mesh.vertices[t[k]]);
      }
      mapped[k] = local[t[k]];
    }
    piece.triangles.push_back(mapped);
  }
  return pieces;
}

}  // namespace antipode::cells
