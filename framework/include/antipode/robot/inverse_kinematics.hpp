#pragma once
/// @file
/// Inverse kinematics of a KinematicChain: joint values, within the joint limits, that put
/// the tip at a target pose X_BaseTip.
///
/// Three solvers:
/// - kDampedLeastSquares (default): Levenberg-Marquardt steps on the pose error (position
///   in m, orientation as an angle-axis vector in rad) with the damping adapted to
///   progress, each step clamped to the joint limits; a descent that stalls restarts from
///   joint values drawn uniformly within the limits from a stream seeded by `seed`. Each
///   step's tip pose and Jacobian come from one pass down the chain, without allocating.
///   A target that no joint values reach by the triangle inequality (the last joint's axis
///   point, which the target fixes up to the last joint's stroke, farther from the first
///   joint's than the links between them span) is refused before any step: kNoSolution
///   with no iterations and no descents.
/// - kKdl: orocos-kdl's ChainIkSolverPos_NR_JL (Newton-Raphson with joint-limit clamping)
///   from the seed only, no restarts: the library's own solver, kept as the baseline the
///   reach benchmark compares with.
/// - kDampedLeastSquaresKdl: the damped solver with each step's tip pose and Jacobian from
///   orocos-kdl's forward-kinematics and Jacobian solvers, and without the reach bound: the
///   baseline the reach benchmarks compare the damped solver's kinematics with (about three
///   times the cost per step on Baxter's arm). The two passes agree to rounding; rounding
///   can change which of two nearly equal steps a descent takes, so the solutions the two
///   find can differ.
///
/// A solution meets the target within `tolerance` (m for each position component, rad for
/// each component of the orientation error). With `max_solutions` > 1 the damped solver
/// keeps restarting after a solution and returns the distinct ones it finds (no two
/// closer than `distinct` in every joint's largest difference), first found first.
///
/// Deterministic: the iteration budget (`max_iterations`) bounds the work and the same
/// inputs give the same result. `timeout_s` > 0 adds a wall-clock bound (the TRAC-IK
/// protocol's 5 ms), which makes the result depend on the machine's speed.
///
/// Threads: a call uses only its arguments; concurrent calls are safe.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"

namespace antipode {

enum class IkSolver { kDampedLeastSquares, kKdl, kDampedLeastSquaresKdl };

enum class IkStatus {
  kSolved,      ///< at least one solution
  kNoSolution,  ///< the iteration budget ran out without one, or the target is out of reach
  kTimedOut,    ///< the wall-clock bound ran out without one
};

const char* to_string(IkStatus status);
/// "dls", "kdl" or "dls_kdl"; ik_solver() reads them, throwing antipode::Error for another
/// name.
const char* to_string(IkSolver solver);
IkSolver ik_solver(const std::string& name);

struct IkOptions {
  IkSolver solver = IkSolver::kDampedLeastSquares;
  double tolerance = 1e-5;          ///< m and rad, per component of the pose error
  int max_iterations = 2000;        ///< over all restarts
  int iterations_per_descent = 15;  ///< a descent that has not converged by then restarts
  double timeout_s = 0.0;           ///< 0: no wall-clock bound
  int max_solutions = 1;
  double distinct = 0.1;   ///< rad (m): how far apart distinct solutions are
  std::uint64_t seed = 0;  ///< the restarts' random stream

  /// Throws antipode::Error naming the offending field.
  void validate() const;
};

struct IkResult {
  IkStatus status = IkStatus::kNoSolution;
  std::vector<Eigen::VectorXd> solutions;  ///< each within the limits, meeting the tolerance
  int iterations = 0;                      ///< over all descents
  int descents = 0;                        ///< 1 + restarts (0: refused out of reach)
};

/// Solves for `X_BaseTip` from `q_seed` (dof() values within the limits; the first descent
/// starts there). Throws antipode::Error for a seed of the wrong size, outside the limits
/// or not finite, a target that is not a finite rigid transform, or invalid options.
IkResult solve_ik(const KinematicChain& chain, const Eigen::Isometry3d& X_BaseTip,
                  const Eigen::VectorXd& q_seed, const IkOptions& options = {});

/// Called with each solution as it is found; returns whether to search on.
using IkVisitor = std::function<bool(const Eigen::VectorXd& q_rad)>;

/// solve_ik, handing each solution to `visit` as it is found, first found first, and
/// stopping when `visit` returns false. The solutions handed over, and the result, are the
/// first ones solve_ik finds with the same options: a caller that wants the first solution
/// with some property (free of collision) stops there and skips the search for the rest.
/// `visit` is called on this thread, and its own time does not count against `timeout_s`;
/// an exception it throws leaves the call.
IkResult solve_ik(const KinematicChain& chain, const Eigen::Isometry3d& X_BaseTip,
                  const Eigen::VectorXd& q_seed, const IkOptions& options, const IkVisitor& visit);

/// The pose error of `X_Actual` against `X_Target` in the base frame: position difference
/// (target - actual, m) then the angle-axis vector of R_target R_actual^T (rad).
Eigen::Matrix<double, 6, 1> pose_error(const Eigen::Isometry3d& X_Target,
                                       const Eigen::Isometry3d& X_Actual);

}  // namespace antipode
