#include "antipode/evaluation/reach_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"

namespace antipode::evaluation {

namespace {

struct SolverFigures {
  int attempts = 0;
  int successes = 0;
  double median_ms = 0.0;
  double mean_ms = 0.0;  // failures included, as TRAC-IK reports it
  double p90_ms = 0.0;
};

std::vector<Eigen::Isometry3d> random_targets(const KinematicChain& chain, int count,
                                              std::uint64_t seed) {
  RandomStream random(seed);
  std::vector<Eigen::Isometry3d> targets;
  targets.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i)
    targets.push_back(chain.forward(chain.random_configuration(random)));
  return targets;
}

SolverFigures measure(const KinematicChain& chain, const std::vector<Eigen::Isometry3d>& targets,
                      IkSolver solver, const ReachBenchOptions& o) {
  IkOptions options;
  options.solver = solver;
  options.tolerance = o.tolerance;
  options.timeout_s = o.timeout_ms / 1000.0;
  options.max_iterations = 1000000;  // the timeout bounds the work
  const Eigen::VectorXd seed = chain.mid_range();
  SolverFigures f;
  std::vector<double> ms;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    options.seed = i;
    const auto start = std::chrono::steady_clock::now();
    const IkResult r = solve_ik(chain, targets[i], seed, options);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    ++f.attempts;
    if (r.status == IkStatus::kSolved) ++f.successes;
  }
  f.median_ms = percentile(ms, 0.5);
  f.p90_ms = percentile(ms, 0.9);
  f.mean_ms = ms.empty() ? 0.0 : std::accumulate(ms.begin(), ms.end(), 0.0) / double(ms.size());
  return f;
}

nlohmann::ordered_json to_json(const SolverFigures& f) {
  return {{"attempts", f.attempts},
          {"successes", f.successes},
          {"median_ms", f.median_ms},
          {"mean_ms", f.mean_ms},
          {"p90_ms", f.p90_ms}};
}

void check(const ReachBenchOptions& o) {
  if (!o.report_path.empty()) check_output_path(o.report_path);
  if (o.ik_poses < 0) throw Error("bench reach: --ik-poses must be at least 0");
  if (!(o.timeout_ms > 0.0)) throw Error("bench reach: --timeout-ms must be positive");
  if (!(o.tolerance > 0.0 && o.tolerance < 1.0))
    throw Error("bench reach: --tolerance must be in (0, 1)");
  if (o.solvers.empty())
    throw Error("bench reach: --solvers names no solver (use dls, kdl, dls_kdl)");
  if (o.scenes < 0) throw Error("bench reach: --scenes must be at least 0");
  if (o.problems < 0) throw Error("bench reach: --problems must be at least 0");
  if (o.ik_poses == 0 && o.scenes == 0 && o.problems == 0)
    throw Error("bench reach: nothing to measure (give --ik-poses, --scenes or --problems)");
  for (const std::string& s : o.solvers) ik_solver(s);  // throws for an unknown name
}

}  // namespace

nlohmann::ordered_json run_reach_bench(const ReachBenchOptions& o) {
  check(o);
  const RobotFile robot_file = read_robot_file(o.robot_path);
  const RobotModel robot = RobotModel::load(robot_file.urdf_path);
  const std::string base = o.base_link.empty() ? robot.root_link() : o.base_link;
  const std::string tip = o.tip_link.empty() ? robot_file.gripper_from : o.tip_link;
  const KinematicChain chain = robot.chain(base, tip);
  const std::vector<Eigen::Isometry3d> targets = random_targets(chain, o.ik_poses, o.seed);
  nlohmann::ordered_json report = {{"robot", o.robot_path},   {"robot_name", robot_file.name},
                                   {"chain", {base, tip}},    {"ik_poses", o.ik_poses},
                                   {"seed", o.seed},          {"timeout_ms", o.timeout_ms},
                                   {"tolerance", o.tolerance}};
  if (o.ik_poses > 0) {
    std::cout << robot_file.name << ": IK, " << chain.dof() << " joints from '" << base << "' to '"
              << tip << "', " << o.ik_poses
              << " random reachable poses, seed at mid-range, tolerance " << o.tolerance
              << ", timeout " << o.timeout_ms << " ms\n";
    std::cout << std::left << std::setw(8) << "solver" << std::setw(22) << "success"
              << std::setw(12) << "median ms" << std::setw(12) << "mean ms"
              << "p90 ms\n";
    for (const std::string& name : o.solvers) {
      const IkSolver solver = ik_solver(name);
      const SolverFigures f = measure(chain, targets, solver, o);
      std::ostringstream rate;
      rate << f.successes << "/" << f.attempts << " " << std::fixed << std::setprecision(2)
           << 100.0 * f.successes / f.attempts << "%";
      std::cout << std::left << std::setw(8) << name << std::setw(22) << rate.str() << std::fixed
                << std::setprecision(4) << std::setw(12) << f.median_ms << std::setw(12)
                << f.mean_ms << f.p90_ms << "\n";
      // "ik" is the project's solver; the others are reported beside it by name.
      report[solver == IkSolver::kDampedLeastSquares ? "ik" : std::string("ik_") + name] =
          to_json(f);
    }
  }
  if (o.scenes > 0) report["planning"] = bench_planning_scenes(o);
  if (o.problems > 0) report["problems"] = bench_planning_problems(o);
  return report;
}

}  // namespace antipode::evaluation
