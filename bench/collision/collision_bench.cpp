// Collision checks per second for Baxter's right arm (robots/baxter/baxter.urdf) at random
// joint values within the limits: against the robot alone, and against a cell - the table,
// the walls of a clutter box on it and 20,000 observed points in a 5 mm octree.

#include <vector>

#include <benchmark/benchmark.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "support/cell_world.hpp"

namespace {

using antipode::collision::ArmCollisionWorld;

const antipode::RobotModel& robot() {
  static const antipode::RobotModel model = antipode::RobotModel::load(ANTIPODE_BENCH_ROBOT);
  return model;
}

// The table, the box and points filling its floor and a pile inside it.
void add_cell(ArmCollisionWorld& world) {
  antipode::bench::add_table_and_box(world);
  const double cx = antipode::bench::kBoxX, cy = antipode::bench::kBoxY;
  antipode::RandomStream random(5);
  std::vector<Eigen::Vector3f> points;
  points.reserve(20000);
  for (int i = 0; i < 20000; ++i) {
    points.emplace_back(float(random.uniform(cx - 0.14, cx + 0.14)),
                        float(random.uniform(cy - 0.14, cy + 0.14)),
                        float(-0.29 + 0.1 * random.uniform() * random.uniform()));
  }
  world.set_points(points, 0.005);
}

std::vector<Eigen::VectorXd> random_configurations(const antipode::KinematicChain& arm, int n) {
  antipode::RandomStream random(1);
  std::vector<Eigen::VectorXd> qs;
  for (int i = 0; i < n; ++i) qs.push_back(arm.random_configuration(random));
  return qs;
}

void check_random(benchmark::State& state, bool with_cell) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  ArmCollisionWorld world(robot(), arm);
  if (with_cell) add_cell(world);
  const std::vector<Eigen::VectorXd> qs = random_configurations(arm, 1000);
  std::size_t i = 0, free = 0, checks = 0;
  for (auto _ : state) {
    free += world.check(qs[i]).free() ? 1 : 0;
    i = (i + 1) % qs.size();
    ++checks;
  }
  state.counters["checks_per_s"] = benchmark::Counter(double(checks), benchmark::Counter::kIsRate);
  state.counters["free_share"] = double(free) / double(checks);
  state.counters["self_pairs"] = double(world.self_pairs().size());
}

void BM_CheckRobotOnly(benchmark::State& state) { check_random(state, false); }
void BM_CheckInCell(benchmark::State& state) { check_random(state, true); }

BENCHMARK(BM_CheckRobotOnly)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell)->Unit(benchmark::kMicrosecond);

}  // namespace
