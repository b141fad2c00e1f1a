#include "sphere_cover.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "antipode/core/error.hpp"

namespace antipode::collision {

namespace {

// A candidate cover in the shape's own frame.
struct Candidate {
  std::vector<Sphere> spheres;
  double bound_m = 0.0;
};

// Cell k of n along a half-length h: its centre.
double cell_centre(double half_m, int n, int k) { return -half_m + half_m / n * (2 * k + 1); }

// A box of half sizes `half` cut into n.x * n.y * n.z sub-boxes. Every axis has cells on
// the boundary, so the worst bound is |sub half sizes| - the smallest sub half size.
Candidate box_cover(const Eigen::Vector3d& half, const Eigen::Vector3i& n) {
  Candidate c;
  const Eigen::Vector3d sub(half.x() / n.x(), half.y() / n.y(), half.z() / n.z());
  const double radius = sub.norm();
  c.bound_m = radius - sub.minCoeff();
  for (int i = 0; i < n.x(); ++i)
    for (int j = 0; j < n.y(); ++j)
      for (int k = 0; k < n.z(); ++k) {
        const Eigen::Vector3d centre(cell_centre(half.x(), n.x(), i),
                                     cell_centre(half.y(), n.y(), j),
                                     cell_centre(half.z(), n.z(), k));
        c.spheres.push_back({centre, radius, (half - centre.cwiseAbs()).minCoeff()});
      }
  return c;
}

// A cylinder (radius R, half length H, along z) covered by spheres on its axis, one per slab
// of a partition of its length. A sphere about the middle of a slab of half width w holds
// the slab with radius sqrt(R^2 + w^2) and reaches that minus R beyond the side. Over an end
// slab the sphere also reaches past the flat end, by its radius minus its depth d below the
// end, which is least, (sqrt(2) - 1) R, for d = R and a slab of width 2 R. So: one sphere
// when H <= R; else an end slab of width up to 2 R at each end, and the middle, if any, cut
// into as few slabs as keep within `target_m` (or within the ends' reach, when larger).
Candidate cylinder_cover(double radius_m, double half_m, double target_m) {
  Candidate c;
  const double R = radius_m;
  if (half_m <= R) {
    const double r = std::hypot(R, half_m);
    c.spheres.push_back({Eigen::Vector3d::Zero(), r, half_m});
    c.bound_m = r - half_m;
    return c;
  }
  const double end_r = std::sqrt(2.0) * R;  // depth R, reaching 2 R into the cylinder
  c.bound_m = end_r - R;
  c.spheres.push_back({Eigen::Vector3d(0, 0, -half_m + R), end_r, R});
  c.spheres.push_back({Eigen::Vector3d(0, 0, half_m - R), end_r, R});
  const double middle_half = half_m - 2.0 * R;
  if (middle_half <= 0.0) return c;
  const double reach = std::max(target_m, c.bound_m);
  const double slab_half = std::sqrt((R + reach) * (R + reach) - R * R);
  const int n = std::max(1, int(std::ceil(middle_half / slab_half - 1e-9)));
  const double r = std::hypot(R, middle_half / n);
  for (int k = 0; k < n; ++k)
    c.spheres.push_back({Eigen::Vector3d(0, 0, cell_centre(middle_half, n, k)), r, R});
  c.bound_m = std::max(c.bound_m, r - R);
  return c;
}

// The grid with the fewest sub-boxes within the target; when none is, the fewest within half
// the target of the best bound (more spheres that barely lower the bound are not worth it).
Candidate best_box(const Eigen::Vector3d& half, double target_m, int max_spheres) {
  std::vector<Candidate> all;
  double least = 1e9;
  for (int x = 1; x <= max_spheres; ++x)
    for (int y = 1; x * y <= max_spheres; ++y)
      for (int z = 1; x * y * z <= max_spheres; ++z) {
        all.push_back(box_cover(half, Eigen::Vector3i(x, y, z)));
        least = std::min(least, all.back().bound_m);
      }
  const double limit = least <= target_m ? target_m : least + 0.5 * target_m;
  Candidate best = all.front();
  for (Candidate& c : all) {
    const bool fits = c.bound_m <= limit, best_fits = best.bound_m <= limit;
    if ((fits && !best_fits) || (fits == best_fits && (c.spheres.size() < best.spheres.size() ||
                                                       (c.spheres.size() == best.spheres.size() &&
                                                        c.bound_m < best.bound_m))))
      best = std::move(c);
  }
  return best;
}

}  // namespace

SphereCover cover_with_spheres(const CollisionPrimitive& shape, double max_overshoot_m,
                               int max_spheres) {
  if (!(max_overshoot_m > 0.0) || max_spheres < 1)
    throw Error("sphere cover: the overshoot and the sphere budget must be positive");
  const Eigen::Vector3d& size = shape.size_m;
  Candidate cover;
  switch (shape.kind) {
    case CollisionPrimitive::Kind::kBox:
      if (!(size.array() > 0.0).all()) throw Error("sphere cover: a box needs positive sizes");
      cover = best_box(0.5 * size, max_overshoot_m, max_spheres);
      break;
    case CollisionPrimitive::Kind::kCylinder:
      if (!(size.x() > 0.0 && size.y() > 0.0))
        throw Error("sphere cover: a cylinder needs a positive radius and length");
      cover = cylinder_cover(size.x(), 0.5 * size.y(), max_overshoot_m);
      break;
    case CollisionPrimitive::Kind::kSphere:
      if (!(size.x() > 0.0)) throw Error("sphere cover: a sphere needs a positive radius");
      cover.spheres.push_back({Eigen::Vector3d::Zero(), size.x(), size.x()});
      break;
  }
  SphereCover out;
  out.overshoot_m = std::max(0.0, cover.bound_m);
  for (const Sphere& s : cover.spheres)
    out.spheres.push_back({shape.X_LinkShape * s.center_m, s.radius_m, s.inner_m});
  return out;
}

}  // namespace antipode::collision
