#include "arm_planner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include "antipode/core/error.hpp"
#include "batched_motion_validator.hpp"
#include "path_shortcut.hpp"
#include "segment_states.hpp"
#include "sphere_kernels.hpp"

namespace antipode::planning {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Uniform samples from a stream seeded per problem, so that a plan depends on the problem's
// seed and not on how many planners the process made before (OMPL's default samplers draw
// their seeds from one process-wide sequence).
class SeededSampler : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::uint64_t seed)
      : ob::RealVectorStateSampler(space) {
    rng_.setLocalSeed(static_cast<std::uint_fast32_t>(seed ^ (seed >> 32)));
  }
};

const std::vector<std::string>& planner_names() {
  static const std::vector<std::string> names = {"RRTConnect", "RRT", "KPIECE1", "PRM", "EST"};
  return names;
}

// A planner of type P, its range set when `range_rad` > 0 (else OMPL's default).
template <class P>
ob::PlannerPtr ranged(const ob::SpaceInformationPtr& si, double range_rad) {
  auto planner = std::make_shared<P>(si);
  if (range_rad > 0.0) planner->setRange(range_rad);
  return planner;
}

// The planner `p` names (check_problem() refused a range for PRM).
ob::PlannerPtr make_planner(const ArmPlanningProblem& p, const ob::SpaceInformationPtr& si) {
  if (p.planner == "RRT") return ranged<og::RRT>(si, p.range_rad);
  if (p.planner == "KPIECE1") return ranged<og::KPIECE1>(si, p.range_rad);
  if (p.planner == "PRM") return std::make_shared<og::PRM>(si);
  if (p.planner == "EST") return ranged<og::EST>(si, p.range_rad);
  return ranged<og::RRTConnect>(si, p.range_rad);
}

void check_problem(const ArmPlanningProblem& p) {
  if (p.arm == nullptr || p.world == nullptr)
    throw Error("arm planning: the problem needs an arm and a collision world");
  const auto dof = static_cast<Eigen::Index>(p.arm->dof());
  if (p.start.size() != dof || p.goal.size() != dof || !p.start.allFinite() ||
      !p.goal.allFinite()) {
    throw Error("arm planning: start and goal need " + std::to_string(dof) +
                " finite joint values each");
  }
  if (!(p.time_limit_s > 0.0)) throw Error("arm planning: time_limit_s must be positive");
  if (!(p.resolution_rad > 0.0)) throw Error("arm planning: resolution_rad must be positive");
  if (!(p.range_rad >= 0.0 && std::isfinite(p.range_rad)))
    throw Error("arm planning: range_rad must be finite and not negative");
  const auto& names = planner_names();
  if (std::find(names.begin(), names.end(), p.planner) == names.end()) {
    throw Error("arm planning: unknown planner '" + p.planner + "'" +
                did_you_mean(p.planner, names) + " (use RRTConnect, RRT, KPIECE1, PRM or EST)");
  }
  if (p.range_rad > 0.0 && p.planner == "PRM")
    throw Error("arm planning: range_rad is for RRTConnect, RRT, KPIECE1 and EST, not PRM");
  if (!(p.late_range_rad >= 0.0 && std::isfinite(p.late_range_rad)))
    throw Error("arm planning: late_range_rad must be finite and not negative");
  if (p.late_after_states < 0) throw Error("arm planning: late_after_states must not be negative");
}

// Sets the range of an RRTConnect or RRT planner (the only ones search() narrows).
void set_range(ob::Planner& planner, double range_rad) {
  if (auto* connect = dynamic_cast<og::RRTConnect*>(&planner)) connect->setRange(range_rad);
  if (auto* rrt = dynamic_cast<og::RRT*>(&planner)) rrt->setRange(range_rad);
}

// Runs the search until `end`: with the problem's range until `late_after_states` states were
// checked, then, without a path yet, with `late_range_rad` on the same trees.
ob::PlannerStatus search(og::SimpleSetup& setup, const ArmPlanningProblem& p,
                         const std::atomic<long>& checks,
                         const ob::PlannerTerminationCondition& end) {
  const bool late = p.late_range_rad > 0.0 && (p.planner == "RRTConnect" || p.planner == "RRT");
  if (!late) return setup.solve(end);
  const long budget = p.late_after_states;
  const ob::PlannerStatus early = setup.solve(ob::plannerOrTerminationCondition(
      end, ob::PlannerTerminationCondition([&checks, budget] { return checks.load() >= budget; })));
  if (early == ob::PlannerStatus::EXACT_SOLUTION || end()) return early;
  set_range(*setup.getPlanner(), p.late_range_rad);
  return setup.solve(end);
}

// A plan that ends before the search when the start or the goal is invalid: outside the
// joint limits, or in collision (with the contact as detail); nullopt when both are valid.
std::optional<ArmPlan> invalid_end(const ArmPlanningProblem& p) {
  ArmPlan plan;
  if (!p.arm->within_limits(p.start)) {
    plan.status = PlanStatus::kStartOutsideLimits;
  } else if (!p.arm->within_limits(p.goal)) {
    plan.status = PlanStatus::kGoalOutsideLimits;
  } else if (const auto c = p.world->check(p.start); !c.free()) {
    plan.status = PlanStatus::kStartInCollision;
    plan.detail = c.str();
  } else if (const auto g = p.world->check(p.goal); !g.free()) {
    plan.status = PlanStatus::kGoalInCollision;
    plan.detail = g.str();
  } else {
    return std::nullopt;
  }
  return plan;
}

Eigen::VectorXd to_eigen(const ob::State* state, std::size_t dof) {
  const auto* s = state->as<ob::RealVectorStateSpace::StateType>();
  Eigen::VectorXd q(static_cast<Eigen::Index>(dof));
  for (std::size_t i = 0; i < dof; ++i) q(static_cast<Eigen::Index>(i)) = s->values[i];
  return q;
}

}  // namespace

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSolved:
      return "solved";
    case PlanStatus::kStartOutsideLimits:
      return "start outside the joint limits";
    case PlanStatus::kGoalOutsideLimits:
      return "goal outside the joint limits";
    case PlanStatus::kStartInCollision:
      return "start in collision";
    case PlanStatus::kGoalInCollision:
      return "goal in collision";
    case PlanStatus::kTimedOut:
      return "timed out";
    case PlanStatus::kCancelled:
      return "cancelled";
  }
  return "?";
}

bool segment_is_free(const collision::ArmCollisionWorld& world, const Eigen::VectorXd& a,
                     const Eigen::VectorXd& b, double resolution_rad, bool rake) {
  std::vector<Eigen::VectorXd> states;
  segment_states(a, b, resolution_rad, true, rake ? collision::kBatchLanes : 0, states);
  return world.first_contact(states) == states.size();
}

ArmPlan plan_arm_motion(const ArmPlanningProblem& p) {
  check_problem(p);
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  if (std::optional<ArmPlan> invalid = invalid_end(p)) return *invalid;
  ArmPlan plan;
  const std::size_t dof = p.arm->dof();
  auto space = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned>(dof));
  ob::RealVectorBounds bounds(static_cast<unsigned>(dof));
  for (std::size_t i = 0; i < dof; ++i) {
    bounds.setLow(static_cast<unsigned>(i), p.arm->limits()[i].lower);
    bounds.setHigh(static_cast<unsigned>(i), p.arm->limits()[i].upper);
  }
  space->setBounds(bounds);
  const std::uint64_t seed = p.seed;
  space->setStateSamplerAllocator(
      [seed](const ob::StateSpace* s) { return std::make_shared<SeededSampler>(s, seed); });
  og::SimpleSetup setup(space);
  const collision::ArmCollisionWorld& world = *p.world;
  std::atomic<long> checks{0};
  setup.setStateValidityChecker([&world, &checks, dof](const ob::State* state) {
    ++checks;
    return world.check(to_eigen(state, dof)).free();
  });
  setup.getSpaceInformation()->setStateValidityCheckingResolution(p.resolution_rad /
                                                                  space->getMaximumExtent());
  setup.getSpaceInformation()->setMotionValidator(std::make_shared<BatchedMotionValidator>(
      setup.getSpaceInformation(), world, p.resolution_rad, p.rake_segments, checks));
  setup.setPlanner(make_planner(p, setup.getSpaceInformation()));
  ob::ScopedState<> start(space), goal(space);
  for (std::size_t i = 0; i < dof; ++i) {
    start[i] = p.start(static_cast<Eigen::Index>(i));
    goal[i] = p.goal(static_cast<Eigen::Index>(i));
  }
  setup.setStartAndGoalStates(start, goal);
  const Clock::time_point t0 = Clock::now();
  const StopToken& stop = p.stop;
  const ob::PlannerTerminationCondition end = ob::plannerOrTerminationCondition(
      ob::timedPlannerTerminationCondition(p.time_limit_s),
      ob::PlannerTerminationCondition([&stop] { return stop.stop_requested(); }));
  const ob::PlannerStatus solved = search(setup, p, checks, end);
  plan.planning_s = seconds_since(t0);
  plan.collision_checks = checks.load();
  if (solved != ob::PlannerStatus::EXACT_SOLUTION) {
    if (stop.stop_requested()) plan.status = PlanStatus::kCancelled;
    return plan;
  }
  for (const ob::State* s : setup.getSolutionPath().getStates())
    plan.path.push_back(to_eigen(s, dof));
  const Clock::time_point t1 = Clock::now();
  if (p.shorten) plan.path = shortcut_path(world, plan.path, p.resolution_rad, p.rake_segments);
  plan.shortening_s = seconds_since(t1);
  plan.status = PlanStatus::kSolved;
  return plan;
}

}  // namespace antipode::planning
