// Planning Baxter's right arm from its neutral configuration to 50 goal configurations above
// a clutter box on the table (goals: inverse kinematics of downward grasps over the box),
// with RRTConnect and the collision world of the cell (table, the box's walls). One plan per
// iteration, goals in turn; the planner's search and the shortcutting are timed apart.

#include <algorithm>
#include <vector>

#include <benchmark/benchmark.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_planner.hpp"
#include "sphere_kernels.hpp"
#include "support/cell_world.hpp"

namespace {

using antipode::collision::ArmCollisionWorld;

// Goal configurations: the grasp frame 12 cm above random points of the box floor, the
// approach straight down, turned about it at random; free ones only.
std::vector<Eigen::VectorXd> goals(const antipode::KinematicChain& arm,
                                   const ArmCollisionWorld& world, std::size_t count) {
  antipode::RandomStream random(2);
  std::vector<Eigen::VectorXd> found;
  while (found.size() < count) {
    Eigen::Isometry3d X =
        antipode::bench::at(random.uniform(0.65, 0.85), random.uniform(-0.3, -0.1), -0.17);
    X.linear() = (Eigen::AngleAxisd(random.uniform(-3.14, 3.14), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()))
                     .toRotationMatrix();  // x (approach) along -z
    antipode::IkOptions options;
    options.seed = found.size();
    const antipode::IkResult ik = antipode::solve_ik(arm, X, arm.mid_range(), options);
    if (ik.status == antipode::IkStatus::kSolved && world.check(ik.solutions[0]).free())
      found.push_back(ik.solutions[0]);
  }
  return found;
}

double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(q * double(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

void plan_neutral_to_above_the_box(benchmark::State& state, antipode::collision::CheckMode mode,
                                   bool rake = true, bool dense = false) {
  antipode::collision::set_sphere_culling(!dense);
  const antipode::RobotModel robot = antipode::RobotModel::load(ANTIPODE_BENCH_ROBOT);
  const antipode::KinematicChain arm = robot.chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = mode;
  ArmCollisionWorld world(robot, arm, {}, options);
  antipode::bench::add_table_and_box(world);
  const std::vector<Eigen::VectorXd> targets = goals(arm, world, 50);
  antipode::planning::ArmPlanningProblem problem;
  problem.arm = &arm;
  problem.world = &world;
  problem.rake_segments = rake;
  problem.start = Eigen::VectorXd(7);
  problem.start << 0, -0.55, 0, 0.75, 0, 1.26, 0;
  std::size_t i = 0, solved = 0;
  std::vector<double> search_ms, shortening_ms;
  for (auto _ : state) {
    problem.goal = targets[i % targets.size()];
    problem.seed = i++;
    const auto plan = antipode::planning::plan_arm_motion(problem);
    solved += plan.status == antipode::planning::PlanStatus::kSolved ? 1 : 0;
    search_ms.push_back(1000.0 * plan.planning_s);
    shortening_ms.push_back(1000.0 * plan.shortening_s);
  }
  state.counters["solved_share"] = double(solved) / double(search_ms.size());
  state.counters["search_median_ms"] = quantile(search_ms, 0.5);
  state.counters["search_p90_ms"] = quantile(search_ms, 0.9);
  state.counters["shortening_median_ms"] = quantile(shortening_ms, 0.5);
  antipode::collision::set_sphere_culling(true);
}

// The collision checks as the planner makes them (spheres, then FCL where they touch; each
// segment's states as a rake), with each segment's states in order, and with FCL alone, side
// by side; and the default with every sphere test of a batch made, none skipped by the links'
// bounding spheres (_Dense). The same paths either way when both searches end within the time
// limit.
void BM_PlanNeutralToAboveTheBox(benchmark::State& state) {
  plan_neutral_to_above_the_box(state, antipode::collision::CheckMode::kSpheresThenExact);
}
void BM_PlanNeutralToAboveTheBox_Dense(benchmark::State& state) {
  plan_neutral_to_above_the_box(state, antipode::collision::CheckMode::kSpheresThenExact, true,
                                true);
}
void BM_PlanNeutralToAboveTheBox_InOrder(benchmark::State& state) {
  plan_neutral_to_above_the_box(state, antipode::collision::CheckMode::kSpheresThenExact, false);
}
void BM_PlanNeutralToAboveTheBox_Exact(benchmark::State& state) {
  plan_neutral_to_above_the_box(state, antipode::collision::CheckMode::kExact);
}
void BM_PlanNeutralToAboveTheBox_ExactInOrder(benchmark::State& state) {
  plan_neutral_to_above_the_box(state, antipode::collision::CheckMode::kExact, false);
}

BENCHMARK(BM_PlanNeutralToAboveTheBox)->Unit(benchmark::kMillisecond)->Iterations(50);
BENCHMARK(BM_PlanNeutralToAboveTheBox_Dense)->Unit(benchmark::kMillisecond)->Iterations(50);
BENCHMARK(BM_PlanNeutralToAboveTheBox_InOrder)->Unit(benchmark::kMillisecond)->Iterations(50);
BENCHMARK(BM_PlanNeutralToAboveTheBox_Exact)->Unit(benchmark::kMillisecond)->Iterations(50);
BENCHMARK(BM_PlanNeutralToAboveTheBox_ExactInOrder)->Unit(benchmark::kMillisecond)->Iterations(50);

}  // namespace
