#pragma once
/// @file
/// Implicit quadric surfaces fitted to points by Taubin's method (paper, section 3.1).

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace antipode {

/// The surface f(u) = 0 with
///   f(u) = c0 ux^2 + c1 uy^2 + c2 uz^2 + c3 ux uy + c4 ux uz + c5 uy uz + c6 ux + c7 uy
///          + c8 uz + c9,
/// in normalised coordinates u = (p - centre_m) / scale_m (the fit is done there so that its
/// matrices are well conditioned). The coefficient vector has unit length up to the
/// generalised-eigenvector normalisation and an arbitrary sign.
struct Quadric {
  Eigen::Matrix<double, 10, 1> coefficients = Eigen::Matrix<double, 10, 1>::Zero();
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double scale_m = 1.0;

  /// f at the point p (metres, the cloud's frame).
  double value(const Eigen::Vector3d& p_m) const;
  /// The gradient of f with respect to u at p. It has the direction of the gradient with
  /// respect to p (they differ by the factor 1 / scale_m), so it normalises to the surface
  /// normal up to sign.
  Eigen::Vector3d gradient(const Eigen::Vector3d& p_m) const;
};

/// Fits a quadric to the points `points[indices[i]]` by Taubin's method: minimise
/// sum f(p)^2 / sum |grad f(p)|^2, i.e. the generalised eigenproblem M c = lambda N c on the
/// 10 x 10 moment matrix M of the monomials and the matrix N of their gradients, solved for
/// the smallest lambda. The constant term is eliminated first (it has no gradient), which
/// leaves a 9 x 9 problem with N positive definite whenever the points span 3-D.
///
/// `centre_m` and `scale_m` (> 0) define the normalised coordinates; use the query point and
/// the neighbourhood radius. Returns nothing for fewer than 9 points or when N is singular
/// (all points on one plane or line): callers fall back to a plane fit.
std::optional<Quadric> fit_taubin_quadric(const std::vector<Eigen::Vector3f>& points,
                                          const std::vector<std::int32_t>& indices,
                                          const Eigen::Vector3d& centre_m, double scale_m);

}  // namespace antipode
