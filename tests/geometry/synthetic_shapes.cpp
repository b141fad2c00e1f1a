#include "synthetic_shapes.hpp"

#include <cmath>

#include "antipode/core/random.hpp"

namespace antipode::testing {
namespace {

// Collects visible surface points: a point with outward normal n at p is kept when it faces
// the sensor at the origin.
class SurfaceSampler {
 public:
  explicit SurfaceSampler(const ShapeOptions& options) : options_(options), random_(options.seed) {
    cloud_.frame = "sensor";
    cloud_.view_origins_m.push_back(Eigen::Vector3f::Zero());
  }

  void add(const Eigen::Vector3d& p, const Eigen::Vector3d& outward) {
    if (outward.dot(-p) <= 0.0) return;
    Eigen::Vector3d noisy = p;
    if (options_.noise_m > 0.0) noisy += options_.noise_m * random_.normal() * p.normalized();
    cloud_.points_m.push_back(noisy.cast<float>());
    cloud_.view_masks.push_back(1u);
  }

  // Samples the parallelogram corner + s * e1 + t * e2 (s, t in [0, 1]).
  void add_patch(const Eigen::Vector3d& corner, const Eigen::Vector3d& e1,
                 const Eigen::Vector3d& e2, const Eigen::Vector3d& outward) {
    const int n1 = std::max(1, static_cast<int>(std::ceil(e1.norm() / options_.spacing_m)));
    const int n2 = std::max(1, static_cast<int>(std::ceil(e2.norm() / options_.spacing_m)));
    for (int i = 0; i <= n1; ++i) {
      for (int j = 0; j <= n2; ++j) add(corner + e1 * i / n1 + e2 * j / n2, outward);
    }
  }

  double spacing() const { return options_.spacing_m; }
  Cloud take() { return std::move(cloud_); }

 private:
  ShapeOptions options_;
  RandomStream random_;
  Cloud cloud_;
};

// Two unit vectors completing `axis` to an orthonormal basis.
std::pair<Eigen::Vector3d, Eigen::Vector3d> basis_around(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d u = axis.unitOrthogonal();
  return {u, axis.cross(u)};
}

}  // namespace

Cloud cylinder_cloud(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& axis_in,
                     double diameter_m, double length_m, const ShapeOptions& options) {
  SurfaceSampler sampler(options);
  const Eigen::Vector3d axis = axis_in.normalized();
  const auto [u, v] = basis_around(axis);
  const double r = diameter_m / 2.0;
  const int around = static_cast<int>(std::ceil(2.0 * M_PI * r / options.spacing_m));
  const int along = static_cast<int>(std::ceil(length_m / options.spacing_m));
  for (int i = 0; i < around; ++i) {
    const double angle = 2.0 * M_PI * i / around;
    const Eigen::Vector3d radial = std::cos(angle) * u + std::sin(angle) * v;
    for (int j = 0; j <= along; ++j) {
      sampler.add(centre_m + radial * r + axis * (length_m * j / along - length_m / 2.0), radial);
    }
  }
  for (const double side : {-1.0, 1.0}) {
    const Eigen::Vector3d cap = centre_m + side * axis * length_m / 2.0;
    for (double rho = 0.0; rho < r; rho += options.spacing_m) {
      const int n = std::max(1, static_cast<int>(std::ceil(2.0 * M_PI * rho / options.spacing_m)));
      for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * M_PI * i / n;
        sampler.add(cap + rho * (std::cos(angle) * u + std::sin(angle) * v), side * axis);
      }
    }
  }
  return sampler.take();
}

Cloud box_cloud(const Eigen::Vector3d& centre_m, const Eigen::Matrix3d& rotation,
                const Eigen::Vector3d& size_m, const ShapeOptions& options) {
  SurfaceSampler sampler(options);
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const Eigen::Vector3d e1 = rotation.col(a1) * size_m[a1];
    const Eigen::Vector3d e2 = rotation.col(a2) * size_m[a2];
    for (const double side : {-1.0, 1.0}) {
      const Eigen::Vector3d outward = side * rotation.col(axis);
      const Eigen::Vector3d face = centre_m + outward * size_m[axis] / 2.0;
      sampler.add_patch(face - e1 / 2.0 - e2 / 2.0, e1, e2, outward);
    }
  }
  return sampler.take();
}

Cloud sphere_cloud(const Eigen::Vector3d& centre_m, double diameter_m,
                   const ShapeOptions& options) {
  SurfaceSampler sampler(options);
  const double r = diameter_m / 2.0;
  const int count = static_cast<int>(4.0 * M_PI * r * r / (options.spacing_m * options.spacing_m));
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {  // Fibonacci sphere: near-uniform spacing
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double rho = std::sqrt(1.0 - z * z);
    const Eigen::Vector3d n(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
    sampler.add(centre_m + r * n, n);
  }
  return sampler.take();
}

Cloud plane_cloud(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& normal_in, double side_m,
                  const ShapeOptions& options) {
  SurfaceSampler sampler(options);
  Eigen::Vector3d normal = normal_in.normalized();
  if (normal.dot(-centre_m) < 0.0) normal = -normal;
  const auto [u, v] = basis_around(normal);
  sampler.add_patch(centre_m - (u + v) * side_m / 2.0, u * side_m, v * side_m, normal);
  return sampler.take();
}

void append(Cloud& cloud, const Cloud& extra) {
  cloud.points_m.insert(cloud.points_m.end(), extra.points_m.begin(), extra.points_m.end());
  cloud.view_masks.insert(cloud.view_masks.end(), extra.view_masks.begin(), extra.view_masks.end());
}

}  // namespace antipode::testing
