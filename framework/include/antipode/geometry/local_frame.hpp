#pragma once
/// @file
/// The local Darboux frame of a surface point (paper, section 3.1): surface normal, the
/// direction of minimum principal curvature ("curvature axis") and their cross product.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace antipode {

/// How a frame was obtained, or why there is none.
enum class FrameStatus : std::uint8_t {
  kQuadric,       ///< Taubin quadric: normal from its gradient, axis from neighbour normals
  kPlanar,        ///< flat neighbourhood: normal and axis from principal component analysis
  kTooFewPoints,  ///< fewer neighbours than LocalFrameOptions::min_points (no frame)
  kCollinear,     ///< the neighbours lie along a line (no normal exists; no frame)
};

const char* to_string(FrameStatus status);

/// F(p) = (normal, binormal, axis) of the paper: a right-handed orthonormal basis with
/// binormal = axis x normal. The normal points to the side the sensor saw the point from
/// (when the caller says which side that is).
struct LocalFrame {
  Eigen::Vector3f origin_m = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitX();
  Eigen::Vector3f binormal = Eigen::Vector3f::UnitY();
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();
  FrameStatus status = FrameStatus::kTooFewPoints;

  bool usable() const { return status == FrameStatus::kQuadric || status == FrameStatus::kPlanar; }
  /// Columns normal, binormal, axis.
  Eigen::Matrix3f basis() const;
};

struct LocalFrameOptions {
  /// Fewer neighbours than this give kTooFewPoints (a quadric has 9 degrees of freedom).
  std::size_t min_points = 10;
  /// How many neighbours' quadric normals enter the curvature-axis estimate (evenly spread
  /// over the neighbourhood).
  std::size_t axis_normals = 50;
  /// The neighbourhood is flat when its smallest covariance eigenvalue is below this
  /// fraction of the covariance trace (1e-3 is an RMS thickness of about 0.7 mm over a 3 cm
  /// ball; a cylinder of 10 cm diameter is about ten times thicker).
  float planar_ratio = 1e-3f;
  /// ... and a line when the middle eigenvalue is below this fraction too.
  float collinear_ratio = 1e-3f;
};

/// Estimates the Darboux frame at `sample_m` from the points `points[neighbours[i]]` (its
/// ball neighbourhood, which should include the sample itself).
///
/// Normal: the gradient of the Taubin quadric at the sample; the principal-component normal
/// when the neighbourhood is flat, the quadric fit is degenerate or its gradient vanishes at
/// the sample. Curvature axis (as agile_grasp does it): the eigenvector with the smallest
/// eigenvalue of sum(n n^T) over the quadric normals n at up to `axis_normals` neighbours,
/// i.e. the direction the surface normals vary least along (a cylinder's axis), made
/// orthogonal to the normal; for a flat neighbourhood, the direction of largest extent. The
/// normal is flipped to have a non-negative dot product with `toward_viewer` (a direction
/// from the point towards the sensor(s) that saw it; pass zero to keep the fit's sign). The
/// axis's sign is chosen so that its largest component is positive (a deterministic choice;
/// a hand is symmetric under flipping it).
///
/// Allocates nothing. Thread-safe.
LocalFrame estimate_local_frame(const std::vector<Eigen::Vector3f>& points,
                                const std::vector<std::int32_t>& neighbours,
                                const Eigen::Vector3f& sample_m,
                                const Eigen::Vector3f& toward_viewer,
                                const LocalFrameOptions& options = {});

}  // namespace antipode
