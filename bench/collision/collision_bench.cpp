// Collision checks per second for Baxter's right arm (robots/baxter/baxter.urdf) at random
// joint values within the limits: against the robot alone, and against a cell - the table,
// the walls of a clutter box on it and 20,000 observed points in a 5 mm octree.

#include <vector>

#include <benchmark/benchmark.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"

namespace {

using antipode::collision::ArmCollisionWorld;

const antipode::RobotModel& robot() {
  static const antipode::RobotModel model = antipode::RobotModel::load(ANTIPODE_BENCH_ROBOT);
  return model;
}

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

// The table top at z = -0.295 and a 0.3 x 0.3 m box with 0.15 m walls centred at
// (0.75, -0.2), the points filling its floor and a pile inside it.
void add_cell(ArmCollisionWorld& world) {
  world.add_box("table", at(0.8, -0.2, -0.32), Eigen::Vector3d(0.8, 1.2, 0.05));
  const double cx = 0.75, cy = -0.2, h = 0.15, t = 0.01;
  world.add_box("wall_x0", at(cx - 0.15, cy, -0.295 + h / 2), Eigen::Vector3d(t, 0.3, h));
  world.add_box("wall_x1", at(cx + 0.15, cy, -0.295 + h / 2), Eigen::Vector3d(t, 0.3, h));
  world.add_box("wall_y0", at(cx, cy - 0.15, -0.295 + h / 2), Eigen::Vector3d(0.3, t, h));
  world.add_box("wall_y1", at(cx, cy + 0.15, -0.295 + h / 2), Eigen::Vector3d(0.3, t, h));
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
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd q(7);
    for (int j = 0; j < 7; ++j) q(j) = random.uniform(arm.limits()[j].lower, arm.limits()[j].upper);
    qs.push_back(q);
  }
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
}

void BM_CheckRobotOnly(benchmark::State& state) { check_random(state, false); }
void BM_CheckInCell(benchmark::State& state) { check_random(state, true); }

BENCHMARK(BM_CheckRobotOnly)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell)->Unit(benchmark::kMicrosecond);

}  // namespace
