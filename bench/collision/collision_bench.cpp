// Collision checks per second for Baxter's right arm (robots/baxter/baxter.urdf) at random
// joint values within the limits: against the robot alone, and against a cell - the table,
// the walls of a clutter box on it and 20,000 observed points in a 5 mm octree. Each in the
// three check modes (FCL alone, spheres then FCL, spheres alone), and the spheres alone at
// each SIMD level, side by side:
//   build/bench/collision/collision_bench --benchmark_filter=Check

#include <vector>

#include <benchmark/benchmark.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "sphere_kernels.hpp"
#include "support/cell_world.hpp"

namespace {

using antipode::collision::ArmCollisionWorld;
using antipode::collision::CheckMode;
using antipode::collision::SimdLevel;

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

void check_random(benchmark::State& state, bool with_cell, CheckMode mode,
                  SimdLevel simd = SimdLevel::kAvx512) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = mode;
  ArmCollisionWorld world(robot(), arm, {}, options);
  if (with_cell) add_cell(world);
  const std::vector<Eigen::VectorXd> qs = random_configurations(arm, 1000);
  const SimdLevel used = antipode::collision::set_simd_level(simd);
  std::size_t i = 0, free = 0, checks = 0;
  for (auto _ : state) {
    free += world.check(qs[i]).free() ? 1 : 0;
    i = (i + 1) % qs.size();
    ++checks;
  }
  antipode::collision::set_simd_level(SimdLevel::kAvx512);
  state.counters["checks_per_s"] = benchmark::Counter(double(checks), benchmark::Counter::kIsRate);
  state.counters["free_share"] = double(free) / double(checks);
  state.counters["self_pairs"] = double(world.self_pairs().size());
  state.counters["spheres"] = double(world.spheres());
  state.SetLabel(mode == CheckMode::kSpheres ? antipode::collision::to_string(used) : "");
}

void BM_CheckRobotOnly_Exact(benchmark::State& s) { check_random(s, false, CheckMode::kExact); }
void BM_CheckRobotOnly_SpheresThenExact(benchmark::State& s) {
  check_random(s, false, CheckMode::kSpheresThenExact);
}
void BM_CheckRobotOnly_Spheres(benchmark::State& s) { check_random(s, false, CheckMode::kSpheres); }
void BM_CheckInCell_Exact(benchmark::State& s) { check_random(s, true, CheckMode::kExact); }
void BM_CheckInCell_SpheresThenExact(benchmark::State& s) {
  check_random(s, true, CheckMode::kSpheresThenExact);
}
void BM_CheckInCell_Spheres(benchmark::State& s) { check_random(s, true, CheckMode::kSpheres); }
void BM_CheckInCell_Spheres_Avx2(benchmark::State& s) {
  check_random(s, true, CheckMode::kSpheres, SimdLevel::kAvx2);
}
void BM_CheckInCell_Spheres_Baseline(benchmark::State& s) {
  check_random(s, true, CheckMode::kSpheres, SimdLevel::kBaseline);
}

// The spheres alone, 16 configurations per call of ArmCollisionWorld::first_contact: the
// spheres of a whole batch are tested at once, whatever it finds.
void check_batches(benchmark::State& state, SimdLevel simd) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = CheckMode::kSpheres;
  ArmCollisionWorld world(robot(), arm, {}, options);
  add_cell(world);
  const std::vector<Eigen::VectorXd> qs = random_configurations(arm, 1024);
  std::vector<std::vector<Eigen::VectorXd>> batches;
  for (std::size_t i = 0; i < qs.size(); i += 16)
    batches.emplace_back(qs.begin() + std::ptrdiff_t(i), qs.begin() + std::ptrdiff_t(i + 16));
  const SimdLevel used = antipode::collision::set_simd_level(simd);
  std::size_t b = 0, checks = 0, contacts = 0;
  for (auto _ : state) {
    contacts += world.first_contact(batches[b]) < 16 ? 1 : 0;
    b = (b + 1) % batches.size();
    checks += 16;
  }
  antipode::collision::set_simd_level(SimdLevel::kAvx512);
  state.counters["checks_per_s"] = benchmark::Counter(double(checks), benchmark::Counter::kIsRate);
  state.SetLabel(antipode::collision::to_string(used));
}
void BM_CheckInCell_Spheres_Batch16(benchmark::State& s) { check_batches(s, SimdLevel::kAvx512); }
void BM_CheckInCell_Spheres_Batch16_Avx2(benchmark::State& s) {
  check_batches(s, SimdLevel::kAvx2);
}
void BM_CheckInCell_Spheres_Batch16_Baseline(benchmark::State& s) {
  check_batches(s, SimdLevel::kBaseline);
}

// Building the world of one capture: the robot, the cell's boxes and its 20,000 points (FCL's
// octree; with spheres also their model and the points' distance grid).
void build_world(benchmark::State& state, CheckMode mode) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = mode;
  for (auto _ : state) {
    ArmCollisionWorld world(robot(), arm, {}, options);
    add_cell(world);
    benchmark::DoNotOptimize(world);
  }
}
void BM_BuildWorldInCell_Exact(benchmark::State& s) { build_world(s, CheckMode::kExact); }
void BM_BuildWorldInCell_SpheresThenExact(benchmark::State& s) {
  build_world(s, CheckMode::kSpheresThenExact);
}

BENCHMARK(BM_BuildWorldInCell_Exact)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildWorldInCell_SpheresThenExact)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckRobotOnly_Exact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckRobotOnly_SpheresThenExact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckRobotOnly_Spheres)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Exact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_SpheresThenExact)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Baseline)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Batch16)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Batch16_Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Batch16_Baseline)->Unit(benchmark::kMicrosecond);

}  // namespace
