#include "plane_fit.hpp"

#include <Eigen/Eigenvalues>

namespace antipode::geometry {

bool refit_plane(const std::vector<Eigen::Vector3f>& points,
                 const std::vector<std::int32_t>& indices, SupportPlane& plane,
                 Eigen::Matrix<float, 3, 2>& spread) {
  if (indices.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const std::int32_t i : indices) mean += points[std::size_t(i)].cast<double>();
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const std::int32_t i : indices) {
    const Eigen::Vector3d d = points[std::size_t(i)].cast<double>() - mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  if (solver.info() != Eigen::Success) return false;
  Eigen::Vector3f normal = solver.eigenvectors().col(0).cast<float>().normalized();
  if (normal.dot(plane.normal) < 0.0f) normal = -normal;
  plane.normal = normal;
  plane.offset = -normal.dot(mean.cast<float>());
  spread.col(0) = solver.eigenvectors().col(2).cast<float>();
  spread.col(1) = solver.eigenvectors().col(1).cast<float>();
  return true;
}

}  // namespace antipode::geometry
