#include "antipode/robot/inverse_kinematics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <kdl/chainjnttojacsolver.hpp>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "kinematic_chain_impl.hpp"

namespace antipode {

const char* to_string(IkStatus status) {
  switch (status) {
    case IkStatus::kSolved:
      return "solved";
    case IkStatus::kNoSolution:
      return "no solution";
    case IkStatus::kTimedOut:
      return "timed out";
  }
  return "?";
}

const char* to_string(IkSolver solver) { return solver == IkSolver::kKdl ? "kdl" : "dls"; }

IkSolver ik_solver(const std::string& name) {
  if (name == "dls") return IkSolver::kDampedLeastSquares;
  if (name == "kdl") return IkSolver::kKdl;
  throw Error("unknown IK solver '" + name + "'" + did_you_mean(name, {"dls", "kdl"}) +
              " (use dls or kdl)");
}

void IkOptions::validate() const {
  auto fail = [](const std::string& what) { throw Error("IK options: " + what); };
  if (!(tolerance > 0.0 && tolerance < 1.0)) fail("tolerance must be in (0, 1)");
  if (max_iterations < 1) fail("max_iterations must be at least 1");
  if (iterations_per_descent < 1) fail("iterations_per_descent must be at least 1");
  if (!(timeout_s >= 0.0 && std::isfinite(timeout_s))) fail("timeout_s must be >= 0");
  if (max_solutions < 1) fail("max_solutions must be at least 1");
  if (!(distinct >= 0.0 && std::isfinite(distinct))) fail("distinct must be >= 0");
}

Eigen::Matrix<double, 6, 1> pose_error(const Eigen::Isometry3d& X_Target,
                                       const Eigen::Isometry3d& X_Actual) {
  Eigen::Matrix<double, 6, 1> e;
  e.head<3>() = X_Target.translation() - X_Actual.translation();
  const Eigen::AngleAxisd turn(X_Target.linear() * X_Actual.linear().transpose());
  e.tail<3>() = turn.angle() * turn.axis();
  return e;
}

namespace {

using Clock = std::chrono::steady_clock;

void check_inputs(const KinematicChain& chain, const Eigen::Isometry3d& X_BaseTip,
                  const Eigen::VectorXd& q_seed, const IkOptions& options) {
  options.validate();
  check_joint_values(chain, q_seed, "IK seed");
  if (!chain.within_limits(q_seed, 1e-9)) throw Error("IK seed: joint values outside the limits");
  const Eigen::Matrix3d r = X_BaseTip.linear();
  if (!X_BaseTip.matrix().allFinite() ||
      !(r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), 1e-6) || r.determinant() < 0) {
    throw Error("IK target: not a finite rigid transform");
  }
}

// The work budget of one solve: iterations, and the wall clock when a timeout is set.
struct Budget {
  int left;
  Clock::time_point deadline;
  bool timed;
  bool timed_out = false;

  bool spend() {
    if (left <= 0) return false;
    if (timed && Clock::now() >= deadline) {
      timed_out = true;
      return false;
    }
    --left;
    return true;
  }
};

// Forward kinematics and Jacobian with the solvers and arrays of one solve.
class Kinematics {
 public:
  explicit Kinematics(const KinematicChain::Impl& impl)
      : fk_(impl.chain),
        jac_(impl.chain),
        q_(impl.chain.getNrOfJoints()),
        j_(impl.chain.getNrOfJoints()) {}

  Eigen::Matrix<double, 6, 1> error(const Eigen::Isometry3d& target, const Eigen::VectorXd& q) {
    q_.data = q;
    KDL::Frame f;
    fk_.JntToCart(q_, f);
    return pose_error(target, to_eigen(f));
  }

  const Eigen::Matrix<double, 6, Eigen::Dynamic>& jacobian(const Eigen::VectorXd& q) {
    q_.data = q;
    jac_.JntToJac(q_, j_);
    return j_.data;
  }

 private:
  KDL::ChainFkSolverPos_recursive fk_;
  KDL::ChainJntToJacSolver jac_;
  KDL::JntArray q_;
  KDL::Jacobian j_;
};

Eigen::VectorXd clamp(const KinematicChain& chain, Eigen::VectorXd q) {
  for (std::size_t i = 0; i < chain.dof(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    q(k) = std::clamp(q(k), chain.limits()[i].lower, chain.limits()[i].upper);
  }
  return q;
}

bool converged(const Eigen::Matrix<double, 6, 1>& e, double tolerance) {
  return e.cwiseAbs().maxCoeff() <= tolerance;
}

// One Levenberg-Marquardt descent from q: returns true with q at a solution, false when it
// stalls, reaches the per-descent limit or the budget runs out.
bool descend(const KinematicChain& chain, Kinematics& kin, const Eigen::Isometry3d& target,
             const IkOptions& options, Budget& budget, Eigen::VectorXd& q, int& iterations) {
  Eigen::Matrix<double, 6, 1> e = kin.error(target, q);
  double cost = e.squaredNorm();
  double lambda = 1e-3;
  const auto n = static_cast<Eigen::Index>(chain.dof());
  for (int step = 0; step < options.iterations_per_descent; ++step) {
    if (converged(e, options.tolerance)) return true;
    if (!budget.spend()) return false;
    ++iterations;
    const auto& j = kin.jacobian(q);
    // The step of the normal equations (J^T J + lambda I) dq = J^T e.
    const Eigen::VectorXd dq = (j.transpose() * j + lambda * Eigen::MatrixXd::Identity(n, n))
                                   .ldlt()
                                   .solve(j.transpose() * e);
    const Eigen::VectorXd trial = clamp(chain, q + dq);
    const Eigen::Matrix<double, 6, 1> trial_e = kin.error(target, trial);
    if (trial_e.squaredNorm() < cost) {
      q = trial, e = trial_e, cost = e.squaredNorm();
      lambda = std::max(lambda / 3.0, 1e-9);
    } else {
      lambda *= 4.0;
      if (lambda > 1e6) return false;  // stuck at a limit or a local minimum
    }
  }
  return converged(e, options.tolerance);
}

bool is_distinct(const std::vector<Eigen::VectorXd>& found, const Eigen::VectorXd& q,
                 double distinct) {
  for (const Eigen::VectorXd& s : found)
    if ((s - q).cwiseAbs().maxCoeff() < distinct) return false;
  return true;
}

// `visit(q)`, its time left out of the budget's wall clock: what the caller does with a
// solution is not the solver's work.
bool visit_outside_budget(const IkVisitor& visit, const Eigen::VectorXd& q, Budget& budget) {
  const Clock::time_point start = Clock::now();
  const bool search_on = visit(q);
  budget.deadline += Clock::now() - start;
  return search_on;
}

IkResult solve_damped(const KinematicChain& chain, const Eigen::Isometry3d& target,
                      const Eigen::VectorXd& q_seed, const IkOptions& options, Budget& budget,
                      const IkVisitor& visit) {
  IkResult result;
  Kinematics kin(*ChainAccess::of(chain));
  RandomStream random(options.seed);
  Eigen::VectorXd q = q_seed;
  while (static_cast<int>(result.solutions.size()) < options.max_solutions) {
    ++result.descents;
    if (descend(chain, kin, target, options, budget, q, result.iterations) &&
        is_distinct(result.solutions, q, options.distinct)) {
      result.solutions.push_back(q);
      if (visit && !visit_outside_budget(visit, q, budget)) break;
    }
    if (budget.left <= 0 || budget.timed_out) break;
    q = chain.random_configuration(random);
  }
  return result;
}

// KDL's Newton-Raphson solver one iteration per call, continuing from where the last call
// stopped, until it converges or the budget runs out (TRAC-IK's protocol for KDL).
IkResult solve_kdl(const KinematicChain& chain, const Eigen::Isometry3d& target,
                   const Eigen::VectorXd& q_seed, const IkOptions& options, Budget& budget,
                   const IkVisitor& visit) {
  const KDL::Chain& kdl_chain = ChainAccess::of(chain)->chain;
  const unsigned n = kdl_chain.getNrOfJoints();
  KDL::JntArray lower(n), upper(n), q(n), out(n);
  for (unsigned i = 0; i < n; ++i) {
    lower(i) = chain.limits()[i].lower;
    upper(i) = chain.limits()[i].upper;
  }
  KDL::ChainFkSolverPos_recursive fk(kdl_chain);
  KDL::ChainIkSolverVel_pinv velocity(kdl_chain);
  KDL::ChainIkSolverPos_NR_JL solver(kdl_chain, lower, upper, fk, velocity, 1, options.tolerance);
  const KDL::Frame frame = to_kdl(target);
  IkResult result;
  result.descents = 1;
  out.data = q_seed;
  while (budget.spend()) {
    ++result.iterations;
    q = out;
    if (solver.CartToJnt(q, frame, out) >= 0) {
      result.solutions.push_back(out.data);
      if (visit) visit(out.data);
      break;
    }
  }
  return result;
}

}  // namespace

IkResult solve_ik(const KinematicChain& chain, const Eigen::Isometry3d& X_BaseTip,
                  const Eigen::VectorXd& q_seed, const IkOptions& options) {
  return solve_ik(chain, X_BaseTip, q_seed, options, IkVisitor());
}

IkResult solve_ik(const KinematicChain& chain, const Eigen::Isometry3d& X_BaseTip,
                  const Eigen::VectorXd& q_seed, const IkOptions& options, const IkVisitor& visit) {
  check_inputs(chain, X_BaseTip, q_seed, options);
  if (chain.dof() == 0)
    throw Error("IK: the chain from '" + chain.base_link() + "' to '" + chain.tip_link() +
                "' has no moving joint");
  Budget budget{options.max_iterations,
                Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(options.timeout_s)),
                options.timeout_s > 0.0};
  IkResult result = options.solver == IkSolver::kKdl
                        ? solve_kdl(chain, X_BaseTip, q_seed, options, budget, visit)
                        : solve_damped(chain, X_BaseTip, q_seed, options, budget, visit);
  if (!result.solutions.empty())
    result.status = IkStatus::kSolved;
  else
    result.status = budget.timed_out ? IkStatus::kTimedOut : IkStatus::kNoSolution;
  return result;
}

}  // namespace antipode
