#include "primitive_meshes.hpp"

#include <cmath>

namespace antipode::cells {
namespace {

constexpr float kPi = 3.14159265358979f;

// A surface of revolution about z: profile points (radius, z) from the bottom pole to the top
// pole, each swept around z in `segments` steps.
TriangleMesh revolve(const std::vector<Eigen::Vector2f>& profile, int segments,
                     const Eigen::Vector2f& xy_scale = Eigen::Vector2f::Ones()) {
  std::vector<SweepRing> rings;
  for (const auto& p : profile)
    rings.push_back({Eigen::Vector3f(0.f, 0.f, p.y()), Eigen::Vector3f(xy_scale.x(), 0.f, 0.f),
                     Eigen::Vector3f(0.f, xy_scale.y(), 0.f), p.x()});
  return sweep_mesh(rings, segments);
}

}  // namespace

TriangleMesh sweep_mesh(const std::vector<SweepRing>& rings, int segments) {
  TriangleMesh mesh;
  std::vector<int> ring_start;
  for (const auto& ring : rings) {
    ring_start.push_back(static_cast<int>(mesh.vertices.size()));
    const int count = ring.radius_m <= 0.f ? 1 : segments;
    for (int s = 0; s < count; ++s) {
      const float a = 2.f * kPi * float(s) / float(segments);
      mesh.vertices.push_back(ring.centre_m +
                              ring.radius_m * (std::cos(a) * ring.u + std::sin(a) * ring.v));
    }
  }
  for (std::size_t r = 0; r + 1 < rings.size(); ++r) {
    const bool low_pole = rings[r].radius_m <= 0.f, high_pole = rings[r + 1].radius_m <= 0.f;
    for (int s = 0; s < segments; ++s) {
      const int n = (s + 1) % segments;
      const int a0 = ring_start[r] + (low_pole ? 0 : s), a1 = ring_start[r] + (low_pole ? 0 : n);
      const int b0 = ring_start[r + 1] + (high_pole ? 0 : s),
                b1 = ring_start[r + 1] + (high_pole ? 0 : n);
      if (!low_pole) mesh.triangles.emplace_back(a0, a1, b0 == b1 ? b0 : b1);
      if (!high_pole) mesh.triangles.emplace_back(a0, b1, b0);
    }
  }
  return mesh;
}

TriangleMesh sweep_piece(const std::vector<SweepRing>& rings, std::size_t first, std::size_t last,
                         int segments) {
  std::vector<SweepRing> piece;
  piece.push_back(rings[first]);
  piece.back().radius_m = 0.f;
  for (std::size_t i = first; i <= last; ++i) piece.push_back(rings[i]);
  piece.push_back(rings[last]);
  piece.back().radius_m = 0.f;
  return sweep_mesh(piece, segments);
}

TriangleMesh revolution_mesh(const std::vector<Eigen::Vector2f>& profile, int segments) {
  return revolve(profile, segments);
}

TriangleMesh box_mesh(const Eigen::Vector3f& h) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                               (i & 4) ? h.z() : -h.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.emplace_back(q[0], q[1], q[2]);
    mesh.triangles.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

TriangleMesh cylinder_mesh(float radius_m, float height_m, int segments) {
  const float z = height_m / 2.f;
  return revolve({{0.f, -z}, {radius_m, -z}, {radius_m, z}, {0.f, z}}, segments);
}

TriangleMesh ellipsoid_mesh(const Eigen::Vector3f& radii_m, int segments) {
  std::vector<Eigen::Vector2f> profile;
  const int rings = segments / 2;
  for (int r = 0; r <= rings; ++r) {
    const float polar = kPi * float(r) / float(rings);
    profile.emplace_back(r == 0 || r == rings ? 0.f : std::sin(polar),
                         -radii_m.z() * std::cos(polar));
  }
  return revolve(profile, segments, radii_m.head<2>());
}

TriangleMesh capsule_mesh(float radius_m, float cylinder_height_m, int segments) {
  std::vector<Eigen::Vector2f> profile;
  const int quarter = segments / 4;
  const float half = cylinder_height_m / 2.f;
  for (int r = 0; r <= quarter; ++r) {
    const float a = 0.5f * kPi * float(r) / float(quarter);
    profile.emplace_back(r == 0 ? 0.f : radius_m * std::sin(a), -half - radius_m * std::cos(a));
  }
  for (int r = quarter; r >= 0; --r) {
    const float a = 0.5f * kPi * float(r) / float(quarter);
    profile.emplace_back(r == 0 ? 0.f : radius_m * std::sin(a), half + radius_m * std::cos(a));
  }
  return revolve(profile, segments);
}

}  // namespace antipode::cells
