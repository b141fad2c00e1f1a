#include "antipode/geometry/local_frame.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "antipode/geometry/quadric.hpp"

namespace antipode {
namespace {

// Eigen-decomposition of the neighbourhood's covariance (eigenvalues ascending).
Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal_components(
    const std::vector<Eigen::Vector3f>& points, const std::vector<std::int32_t>& neighbours) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const std::int32_t i : neighbours)
    mean += points[static_cast<std::size_t>(i)].cast<double>();
  mean /= static_cast<double>(neighbours.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const std::int32_t i : neighbours) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)].cast<double>() - mean;
    covariance.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance / static_cast<double>(neighbours.size()));
  return solver;
}

// Smallest-eigenvalue eigenvector of sum(n n^T) over the quadric normals at (up to `count`)
// neighbours spread evenly through the list; zero when no normal could be computed.
Eigen::Vector3d least_varying_normal_direction(const Quadric& quadric,
                                               const std::vector<Eigen::Vector3f>& points,
                                               const std::vector<std::int32_t>& neighbours,
                                               std::size_t count) {
  const std::size_t stride =
      std::max<std::size_t>(1, neighbours.size() / std::max<std::size_t>(count, 1));
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  int used = 0;
  for (std::size_t k = 0; k < neighbours.size() && used < static_cast<int>(count); k += stride) {
    const Eigen::Vector3d g =
        quadric.gradient(points[static_cast<std::size_t>(neighbours[k])].cast<double>());
    const double norm = g.norm();
    if (!(norm > 1e-12)) continue;
    scatter.noalias() += (g / norm) * (g / norm).transpose();
    ++used;
  }
  if (used < 2) return Eigen::Vector3d::Zero();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(scatter);
  return solver.eigenvectors().col(0);
}

// Fills binormal and fixes signs; `axis_guess` need not be orthogonal to the normal.
bool complete_frame(LocalFrame& frame, Eigen::Vector3d normal, Eigen::Vector3d axis_guess,
                    const Eigen::Vector3f& toward_viewer) {
  normal.normalize();
  if (normal.dot(toward_viewer.cast<double>()) < 0.0) normal = -normal;
  Eigen::Vector3d axis = axis_guess - axis_guess.dot(normal) * normal;
  if (!(axis.norm() > 1e-6)) return false;
  axis.normalize();
  Eigen::Index largest = 0;
  axis.cwiseAbs().maxCoeff(&largest);
  if (axis[largest] < 0.0) axis = -axis;
  frame.normal = normal.cast<float>();
  frame.axis = axis.cast<float>();
  frame.binormal = frame.axis.cross(frame.normal).normalized();
  return true;
}

// Any direction orthogonal to `normal`: the eigenvector used when the axis estimate fails.
Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& normal) { return normal.unitOrthogonal(); }

// The frame from the quadric's gradient at the sample and the neighbours' normals; false
// when the gradient vanishes at the sample.
bool quadric_frame(const Quadric& quadric, const std::vector<Eigen::Vector3f>& points,
                   const std::vector<std::int32_t>& neighbours,
                   const Eigen::Vector3f& toward_viewer, const LocalFrameOptions& options,
                   LocalFrame& frame) {
  const Eigen::Vector3d normal = quadric.gradient(frame.origin_m.cast<double>());
  if (!(normal.norm() > 1e-6 * quadric.coefficients.norm())) return false;
  const Eigen::Vector3d axis =
      least_varying_normal_direction(quadric, points, neighbours, options.axis_normals);
  return complete_frame(frame, normal, axis, toward_viewer) ||
         complete_frame(frame, normal, any_orthogonal(normal), toward_viewer);
}

}  // namespace

const char* to_string(FrameStatus status) {
  switch (status) {
    case FrameStatus::kQuadric:
      return "quadric";
    case FrameStatus::kPlanar:
      return "planar";
    case FrameStatus::kTooFewPoints:
      return "too few points";
    case FrameStatus::kCollinear:
      return "collinear";
  }
  return "?";
}

Eigen::Matrix3f LocalFrame::basis() const {
  Eigen::Matrix3f rotation;
  rotation << normal, binormal, axis;
  return rotation;
}

LocalFrame estimate_local_frame(const std::vector<Eigen::Vector3f>& points,
                                const std::vector<std::int32_t>& neighbours,
                                const Eigen::Vector3f& sample_m,
                                const Eigen::Vector3f& toward_viewer,
                                const LocalFrameOptions& options) {
  LocalFrame frame;
  frame.origin_m = sample_m;
  if (neighbours.size() < std::max<std::size_t>(options.min_points, 9)) {
    frame.status = FrameStatus::kTooFewPoints;
    return frame;
  }
  const auto pca = principal_components(points, neighbours);
  const Eigen::Vector3d lambda = pca.eigenvalues();
  const double trace = lambda.sum();
  const Eigen::Matrix3d& vectors = pca.eigenvectors();
  if (!(trace > 0.0) || lambda[1] < options.collinear_ratio * trace) {
    frame.status = FrameStatus::kCollinear;
    return frame;
  }
  const double scale = std::sqrt(trace);
  if (lambda[0] >= options.planar_ratio * trace) {
    const auto quadric = fit_taubin_quadric(points, neighbours, sample_m.cast<double>(), scale);
    if (quadric && quadric_frame(*quadric, points, neighbours, toward_viewer, options, frame)) {
      frame.status = FrameStatus::kQuadric;
      return frame;
    }
  }
  frame.status = FrameStatus::kPlanar;
  if (!complete_frame(frame, vectors.col(0), vectors.col(2), toward_viewer)) {
    complete_frame(frame, vectors.col(0), any_orthogonal(vectors.col(0)), toward_viewer);
  }
  return frame;
}

}  // namespace antipode
