#pragma once
// Execution noise: where the hand really goes when a grasp is executed. A real arm reaches a
// commanded pose only to within its repeatability (Baxter's arm: a few millimetres); the cell
// can add such an error, drawn afresh for every attempt.

#include <cstdint>

#include <Eigen/Geometry>

namespace antipode::cells {

/// The error added to each executed hand pose: independent normal draws per axis.
struct ExecutionNoise {
  double position_m = 0.0;    ///< standard deviation of the offset along each base axis
  double rotation_rad = 0.0;  ///< standard deviation of each component of a small rotation
  std::uint64_t seed = 0;     ///< another seed: other draws on the same scene (bench replicates)

  bool none() const { return position_m == 0.0 && rotation_rad == 0.0; }
};

/// `X_BaseHand` moved by the noise of attempt `attempt` of the cell seeded with `cell_seed`:
/// the same (cell_seed, noise.seed, attempt) always give the same pose, and zero noise gives
/// `X_BaseHand` itself. The rotation turns the hand about its own origin (the palm face
/// centre), expressed in the base frame.
Eigen::Isometry3d executed_pose(const Eigen::Isometry3d& X_BaseHand, const ExecutionNoise& noise,
                                std::uint64_t cell_seed, int attempt);

}  // namespace antipode::cells
