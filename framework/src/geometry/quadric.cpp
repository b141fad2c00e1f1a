#include "antipode/geometry/quadric.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace antipode {
namespace {

using Vector10d = Eigen::Matrix<double, 10, 1>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

// The monomials x^2, y^2, z^2, xy, xz, yz, x, y, z, 1 of u.
Vector10d monomials(const Eigen::Vector3d& u) {
  Vector10d l;
  l << u.x() * u.x(), u.y() * u.y(), u.z() * u.z(), u.x() * u.y(), u.x() * u.z(), u.y() * u.z(),
      u.x(), u.y(), u.z(), 1.0;
  return l;
}

// N = sum over points of J J^T, where J (9 x 3) holds the gradients of the nine non-constant
// monomials. Every entry is a first or second moment, so N follows from `sums` (the sums of
// the monomials over the points) without another pass.
Matrix9d gradient_moments(const Vector10d& sums) {
  const double xx = sums[0], yy = sums[1], zz = sums[2], xy = sums[3], xz = sums[4];
  const double yz = sums[5], x = sums[6], y = sums[7], z = sums[8], n = sums[9];
  Matrix9d N = Matrix9d::Zero();
  N(0, 0) = 4 * xx, N(0, 3) = 2 * xy, N(0, 4) = 2 * xz, N(0, 6) = 2 * x;
  N(1, 1) = 4 * yy, N(1, 3) = 2 * xy, N(1, 5) = 2 * yz, N(1, 7) = 2 * y;
  N(2, 2) = 4 * zz, N(2, 4) = 2 * xz, N(2, 5) = 2 * yz, N(2, 8) = 2 * z;
  N(3, 3) = xx + yy, N(3, 4) = yz, N(3, 5) = xz, N(3, 6) = y, N(3, 7) = x;
  N(4, 4) = xx + zz, N(4, 5) = xy, N(4, 6) = z, N(4, 8) = x;
  N(5, 5) = yy + zz, N(5, 7) = z, N(5, 8) = y;
  N(6, 6) = n, N(7, 7) = n, N(8, 8) = n;
  return N.selfadjointView<Eigen::Upper>();
}

}  // namespace

double Quadric::value(const Eigen::Vector3d& p_m) const {
  return coefficients.dot(monomials((p_m - centre_m) / scale_m));
}

Eigen::Vector3d Quadric::gradient(const Eigen::Vector3d& p_m) const {
  const Eigen::Vector3d u = (p_m - centre_m) / scale_m;
  const auto& c = coefficients;
  return {2 * c[0] * u.x() + c[3] * u.y() + c[4] * u.z() + c[6],
          2 * c[1] * u.y() + c[3] * u.x() + c[5] * u.z() + c[7],
          2 * c[2] * u.z() + c[4] * u.x() + c[5] * u.y() + c[8]};
}

std::optional<Quadric> fit_taubin_quadric(const std::vector<Eigen::Vector3f>& points,
                                          const std::vector<std::int32_t>& indices,
                                          const Eigen::Vector3d& centre_m, double scale_m) {
  if (indices.size() < 9 || !(scale_m > 0.0)) return std::nullopt;
  Eigen::Matrix<double, 10, 10> moments = Eigen::Matrix<double, 10, 10>::Zero();
  for (const std::int32_t i : indices) {
    const Vector10d l =
        monomials((points[static_cast<std::size_t>(i)].cast<double>() - centre_m) / scale_m);
    moments.noalias() += l * l.transpose();
  }
  const Vector10d sums = moments.col(9);
  const double n = sums[9];
  // Minimising over the constant term leaves the centred moments of the other monomials.
  const Matrix9d M =
      moments.topLeftCorner<9, 9>() - sums.head<9>() * sums.head<9>().transpose() / n;
  const Matrix9d N = gradient_moments(sums);
  if (Eigen::LLT<Matrix9d>(N).info() != Eigen::Success) return std::nullopt;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix9d> solver(M, N);
  if (solver.info() != Eigen::Success) return std::nullopt;
  const Eigen::Matrix<double, 9, 1> c = solver.eigenvectors().col(0);
  if (!c.allFinite()) return std::nullopt;
  Quadric quadric;
  quadric.coefficients.head<9>() = c;
  quadric.coefficients[9] = -sums.head<9>().dot(c) / n;
  quadric.centre_m = centre_m;
  quadric.scale_m = scale_m;
  return quadric;
}

}  // namespace antipode
