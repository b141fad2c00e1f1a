#include "antipode/robot/inverse_kinematics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <Eigen/Cholesky>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>
#include <kdl/chainjnttojacsolver.hpp>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "chain_evaluator.hpp"
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

const char* to_string(IkSolver solver) {
  switch (solver) {
    case IkSolver::kDampedLeastSquares:
      return "dls";
    case IkSolver::kKdl:
      return "kdl";
    case IkSolver::kDampedLeastSquaresKdl:
      return "dls_kdl";
  }
  return "?";
}

IkSolver ik_solver(const std::string& name) {
  for (const IkSolver s :
       {IkSolver::kDampedLeastSquares, IkSolver::kKdl, IkSolver::kDampedLeastSquaresKdl})
    if (name == to_string(s)) return s;
  throw Error("unknown IK solver '" + name + "'" + did_you_mean(name, {"dls", "kdl", "dls_kdl"}) +
              " (use dls, kdl or dls_kdl)");
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

// The tip pose and Jacobian of one solve: the chain's one-pass evaluator, or orocos-kdl's
// solvers (kDampedLeastSquaresKdl).
class Kinematics {
 public:
  Kinematics(const KinematicChain& chain, IkSolver solver)
      : one_pass_(ChainEvaluator::of(chain)),
        kdl_(solver == IkSolver::kDampedLeastSquaresKdl ? ChainAccess::of(chain) : nullptr) {
    if (kdl_ == nullptr) return;
    fk_.emplace(kdl_->chain);
    jac_.emplace(kdl_->chain);
    q_.resize(kdl_->chain.getNrOfJoints());
    j_.resize(kdl_->chain.getNrOfJoints());
  }

  // False when the target is certainly beyond the chain's reach (the one-pass kinematics
  // only: the KDL baseline searches regardless). The margin covers the tolerance: up to
  // sqrt(3) tolerance in position, and the orientation's acting on the last joint's lever.
  bool may_reach(const Eigen::Isometry3d& target, double tolerance) const {
    if (kdl_ != nullptr) return true;
    const double margin = 1e-3 + std::sqrt(3.0) * tolerance * (1.0 + one_pass_.lever_m());
    return one_pass_.may_reach(target, margin);
  }

  void evaluate(const Eigen::VectorXd& q, Eigen::Isometry3d& X_BaseTip,
                ChainEvaluator::Jacobian& J) {
    if (kdl_ == nullptr) return one_pass_.evaluate(q, X_BaseTip, J);
    q_.data = q;
    KDL::Frame f;
    fk_->JntToCart(q_, f);
    X_BaseTip = to_eigen(f);
    jac_->JntToJac(q_, j_);
    J = j_.data;
  }

 private:
  const ChainEvaluator& one_pass_;
  const KinematicChain::Impl* kdl_;
  std::optional<KDL::ChainFkSolverPos_recursive> fk_;
  std::optional<KDL::ChainJntToJacSolver> jac_;
  KDL::JntArray q_;
  KDL::Jacobian j_;
};

// The pose error, its squared norm and the Jacobian at one joint vector.
struct Evaluation {
  Eigen::VectorXd q;
  Eigen::Matrix<double, 6, 1> e;
  ChainEvaluator::Jacobian J;
  double cost = 0.0;
};

void evaluate(Kinematics& kin, const Eigen::Isometry3d& target, Evaluation& at) {
  Eigen::Isometry3d X_BaseTip;
  kin.evaluate(at.q, X_BaseTip, at.J);
  at.e = pose_error(target, X_BaseTip);
  at.cost = at.e.squaredNorm();
}

// x = A^-1 b for the damped system A (symmetric, positive definite by lambda > 0): Cholesky,
// or LDLT with pivoting where rounding leaves A not numerically positive definite.
template <typename Matrix, typename Vector>
Vector solve_spd(const Matrix& a, const Vector& b) {
  const Eigen::LLT<Matrix> llt(a);
  if (llt.info() == Eigen::Success) return llt.solve(b);
  return a.ldlt().solve(b);
}

// dq = (J^T J + lambda I)^-1 J^T e, without allocating. From six joints on, the same step
// as J^T (J J^T + lambda I)^-1 e, which factors a 6 x 6 matrix whatever the chain's length.
void damped_step(const ChainEvaluator::Jacobian& J, const Eigen::Matrix<double, 6, 1>& e,
                 double lambda, Eigen::VectorXd& dq) {
  if (J.cols() >= 6) {
    Eigen::Matrix<double, 6, 6> a = J.lazyProduct(J.transpose());
    a.diagonal().array() += lambda;
    const Eigen::Matrix<double, 6, 1> y = solve_spd(a, e);
    dq.noalias() = J.transpose() * y;
    return;
  }
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
  Small a = J.transpose().lazyProduct(J);
  a.diagonal().array() += lambda;
  const SmallVector b = J.transpose() * e;
  dq = solve_spd(a, b);
}

// The joint limits as two vectors, for clamping every step.
struct Limits {
  Eigen::VectorXd lower, upper;
  explicit Limits(const KinematicChain& chain)
      : lower(static_cast<Eigen::Index>(chain.dof())),
        upper(static_cast<Eigen::Index>(chain.dof())) {
    for (std::size_t i = 0; i < chain.dof(); ++i) {
      lower(static_cast<Eigen::Index>(i)) = chain.limits()[i].lower;
      upper(static_cast<Eigen::Index>(i)) = chain.limits()[i].upper;
    }
  }
  void clamp(Eigen::VectorXd& q) const { q = q.cwiseMax(lower).cwiseMin(upper); }
};

bool converged(const Eigen::Matrix<double, 6, 1>& e, double tolerance) {
  return e.cwiseAbs().maxCoeff() <= tolerance;
}

// The arrays of one solve's descents, sized once.
struct Workspace {
  Evaluation at;     // the descent's current joint values
  Evaluation trial;  // the step's
  Eigen::VectorXd dq;
};

// One Levenberg-Marquardt descent from `work.at.q`: returns true with it at a solution,
// false when it stalls, reaches the per-descent limit or the budget runs out.
bool descend(const Limits& limits, Kinematics& kin, const Eigen::Isometry3d& target,
             const IkOptions& options, Budget& budget, Workspace& work, int& iterations) {
  evaluate(kin, target, work.at);
  double lambda = 1e-3;
  for (int step = 0; step < options.iterations_per_descent; ++step) {
    if (converged(work.at.e, options.tolerance)) return true;
    if (!budget.spend()) return false;
    ++iterations;
    damped_step(work.at.J, work.at.e, lambda, work.dq);
    work.trial.q = work.at.q + work.dq;
    limits.clamp(work.trial.q);
    evaluate(kin, target, work.trial);
    if (work.trial.cost < work.at.cost) {
      std::swap(work.at, work.trial);
      lambda = std::max(lambda / 3.0, 1e-9);
    } else {
      lambda *= 4.0;
      if (lambda > 1e6) return false;  // stuck at a limit or a local minimum
    }
  }
  return converged(work.at.e, options.tolerance);
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
  Kinematics kin(chain, options.solver);
  RandomStream random(options.seed);
  if (!kin.may_reach(target, options.tolerance)) return result;
  const Limits limits(chain);
  Workspace work;
  work.at.q = q_seed;
  while (static_cast<int>(result.solutions.size()) < options.max_solutions) {
    ++result.descents;
    if (descend(limits, kin, target, options, budget, work, result.iterations) &&
        is_distinct(result.solutions, work.at.q, options.distinct)) {
      result.solutions.push_back(work.at.q);
      if (visit && !visit_outside_budget(visit, work.at.q, budget)) break;
    }
    if (budget.left <= 0 || budget.timed_out) break;
    work.at.q = chain.random_configuration(random);
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
