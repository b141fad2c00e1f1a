// Collision checks per second for Baxter's right arm (robots/baxter/baxter.urdf) at random
// joint values within the limits: against the robot alone, and against a cell - the table,
// the walls of a clutter box on it and 20,000 observed points in a 5 mm octree. Each in the
// three check modes (FCL alone, spheres then FCL, spheres alone), and the spheres alone at
// each SIMD level, side by side:
//   build/bench/collision/collision_bench --benchmark_filter=Check
// Also the octree of a capture's points, built per leaf and point by point, the reach check
// of grasps over the box with its searches, and the arm's inverse kinematics with its two
// kinematics (--benchmark_filter='Octree|Reach|Ik'); and one pair of shapes as the checks
// confirm what the spheres flag, FCL alone or the primitives' quick tests first
// (--benchmark_filter=ConfirmPair).

#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>

#include "antipode/core/random.hpp"
#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "points_octree.hpp"
#include "primitive_tests.hpp"
#include "reach_check.hpp"
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
  qs.reserve(std::size_t(n));
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
// spheres of a whole batch are tested at once, whatever it finds. In the cell (its boxes and
// points) or among its boxes alone; `dense`: every sphere pair and sphere-box pair tested,
// none skipped by the links' bounding spheres (the same answers).
void check_batches(benchmark::State& state, SimdLevel simd, bool points = true,
                   bool dense = false) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = CheckMode::kSpheres;
  ArmCollisionWorld world(robot(), arm, {}, options);
  if (points)
    add_cell(world);
  else
    antipode::bench::add_table_and_box(world);
  antipode::collision::set_sphere_culling(!dense);
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
  antipode::collision::set_sphere_culling(true);
  state.counters["checks_per_s"] = benchmark::Counter(double(checks), benchmark::Counter::kIsRate);
  state.SetLabel(antipode::collision::to_string(used));
}
void BM_CheckInCell_Spheres_Batch16(benchmark::State& s) { check_batches(s, SimdLevel::kAvx512); }
void BM_CheckInCell_Spheres_Batch16_Dense(benchmark::State& s) {
  check_batches(s, SimdLevel::kAvx512, true, true);
}
void BM_CheckAmongBoxes_Spheres_Batch16(benchmark::State& s) {
  check_batches(s, SimdLevel::kAvx512, false);
}
void BM_CheckAmongBoxes_Spheres_Batch16_Dense(benchmark::State& s) {
  check_batches(s, SimdLevel::kAvx512, false, true);
}
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

// A capture's size: 460,800 points (a 640 x 720 image) in rows over the table and a mound
// in the box, as a depth camera lists them, in a 1 cm octree.
std::vector<Eigen::Vector3f> capture_points() {
  std::vector<Eigen::Vector3f> points;
  for (int row = 0; row < 720; ++row) {
    for (int col = 0; col < 640; ++col) {
      const double x = 0.3 + 0.9 * col / 640.0, y = -0.7 + 1.0 * row / 720.0;
      const double r = std::hypot(x - antipode::bench::kBoxX, y - antipode::bench::kBoxY);
      const double z = antipode::bench::kTableZ + (r < 0.15 ? 0.1 * (1.0 - r / 0.15) : 0.0);
      points.emplace_back(float(x), float(y), float(z));
    }
  }
  return points;
}

void BM_PointsOctree(benchmark::State& s) {
  const std::vector<Eigen::Vector3f> points = capture_points();
  std::size_t leaves = 0;
  for (auto _ : s) leaves = antipode::collision::points_octree(points, 0.01)->getNumLeafNodes();
  s.counters["leaves"] = double(leaves);
}
void BM_PointsOctree_PointByPoint(benchmark::State& s) {
  const std::vector<Eigen::Vector3f> points = capture_points();
  std::size_t leaves = 0;
  for (auto _ : s)
    leaves = antipode::collision::points_octree_point_by_point(points, 0.01)->getNumLeafNodes();
  s.counters["leaves"] = double(leaves);
}

// The selector's reach check (reach_check.hpp) of grasps over the box: a 13 x 7 grid from
// x = 0.45 to 1.05 m (beyond the arm's reach from above past about 0.75) at the height of the
// pile, each from above and tilted 45 degrees, round-robin. The selector's default (the
// first free pair of IK solutions, FCL alone, the one-pass kinematics) beside the same with
// orocos-kdl's kinematics, and the reach bench's baseline (every IK solution at the grasp
// first, FCL alone, orocos-kdl's kinematics); also the first free pair with spheres then FCL.
std::vector<Eigen::Isometry3d> grasps_over_the_box() {
  std::vector<Eigen::Isometry3d> grasps;
  for (int i = 0; i < 13; ++i) {
    for (int j = 0; j < 7; ++j) {
      for (const Eigen::Vector3d& approach :
           {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(1, 0, -1)}) {
        Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
        X.linear().col(0) = approach.normalized();
        X.linear().col(1) = Eigen::Vector3d::UnitY();
        X.linear().col(2) = X.linear().col(0).cross(X.linear().col(1));
        X.translation() = Eigen::Vector3d(0.45 + 0.05 * i, -0.35 + 0.05 * j, -0.08);
        grasps.push_back(X);
      }
    }
  }
  return grasps;
}

void reach_checks(benchmark::State& state, antipode::collision::ReachSearch search, CheckMode mode,
                  antipode::IkSolver solver) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::collision::CollisionOptions options;
  options.mode = mode;
  ArmCollisionWorld world(robot(), arm, {}, options);
  add_cell(world);
  const std::vector<Eigen::Isometry3d> grasps = grasps_over_the_box();
  antipode::collision::ReachOptions reach;
  reach.search = search;
  reach.ik.solver = solver;
  std::size_t i = 0, reachable = 0, checks = 0;
  for (auto _ : state) {
    const auto r = antipode::collision::check_reach(arm, world, grasps[i], arm.mid_range(), reach);
    reachable += r.status == antipode::collision::ReachStatus::kReachable ? 1 : 0;
    i = (i + 1) % grasps.size();
    ++checks;
  }
  state.counters["reachable_share"] = double(reachable) / double(checks);
}
using antipode::IkSolver;
using antipode::collision::ReachSearch;
void BM_ReachCheck_FirstFree(benchmark::State& s) {
  reach_checks(s, ReachSearch::kFirstFree, CheckMode::kExact, IkSolver::kDampedLeastSquares);
}
void BM_ReachCheck_FirstFree_KdlKinematics(benchmark::State& s) {
  reach_checks(s, ReachSearch::kFirstFree, CheckMode::kExact, IkSolver::kDampedLeastSquaresKdl);
}
void BM_ReachCheck_FirstFree_SpheresThenExact(benchmark::State& s) {
  reach_checks(s, ReachSearch::kFirstFree, CheckMode::kSpheresThenExact,
               IkSolver::kDampedLeastSquares);
}
void BM_ReachCheck_Baseline(benchmark::State& s) {
  reach_checks(s, ReachSearch::kExhaustive, CheckMode::kExact, IkSolver::kDampedLeastSquaresKdl);
}

// Inverse kinematics of the right arm (inverse_kinematics.hpp): the damped solver with its own
// kinematics and with orocos-kdl's (dls_kdl), at the
// poses of random joint vectors, seeded at mid-range: the first solution (what a reachable
// grasp costs), and solutions until the whole budget is spent (2,000 iterations: what a
// grasp the arm cannot take costs when it lies within the arm's reach bound).
void ik(benchmark::State& state, IkSolver solver, bool first_only) {
  const antipode::KinematicChain arm = robot().chain("base", "right_gripper");
  antipode::RandomStream random(3);
  std::vector<Eigen::Isometry3d> targets;
  targets.reserve(200);
  for (int i = 0; i < 200; ++i) targets.push_back(arm.forward(arm.random_configuration(random)));
  antipode::IkOptions options;
  options.solver = solver;
  if (!first_only) options.max_solutions = options.max_iterations;
  std::size_t i = 0, solved = 0, calls = 0;
  double iterations = 0.0;
  for (auto _ : state) {
    const antipode::IkResult r = antipode::solve_ik(arm, targets[i], arm.mid_range(), options);
    solved += r.status == antipode::IkStatus::kSolved ? 1 : 0;
    iterations += r.iterations;
    i = (i + 1) % targets.size();
    ++calls;
  }
  state.counters["solved_share"] = double(solved) / double(calls);
  state.counters["iterations"] = iterations / double(calls);
}
void BM_Ik_First(benchmark::State& s) { ik(s, IkSolver::kDampedLeastSquares, true); }
void BM_Ik_First_KdlKinematics(benchmark::State& s) {
  ik(s, IkSolver::kDampedLeastSquaresKdl, true);
}
void BM_Ik_WholeBudget(benchmark::State& s) { ik(s, IkSolver::kDampedLeastSquares, false); }
void BM_Ik_WholeBudget_KdlKinematics(benchmark::State& s) {
  ik(s, IkSolver::kDampedLeastSquaresKdl, false);
}

BENCHMARK(BM_ReachCheck_FirstFree)->Unit(benchmark::kMillisecond)->Iterations(364);
BENCHMARK(BM_ReachCheck_FirstFree_KdlKinematics)->Unit(benchmark::kMillisecond)->Iterations(364);
BENCHMARK(BM_ReachCheck_FirstFree_SpheresThenExact)->Unit(benchmark::kMillisecond)->Iterations(364);
BENCHMARK(BM_ReachCheck_Baseline)->Unit(benchmark::kMillisecond)->Iterations(364);
BENCHMARK(BM_Ik_First)->Unit(benchmark::kMicrosecond)->Iterations(1000);
BENCHMARK(BM_Ik_First_KdlKinematics)->Unit(benchmark::kMicrosecond)->Iterations(1000);
BENCHMARK(BM_Ik_WholeBudget)->Unit(benchmark::kMillisecond)->Iterations(200);
BENCHMARK(BM_Ik_WholeBudget_KdlKinematics)->Unit(benchmark::kMillisecond)->Iterations(200);
// A pair as the spheres flag them: Baxter's forearm cylinder (radius 6 cm, 27 cm long) and a
// 4 cm wall (30 x 30 cm) facing it from a random direction, its face from 1 cm inside the
// cylinder to 2.5 cm outside it (the spheres' overshoot at a flat end).
struct Pair {
  antipode::collision::PlacedPrimitive cylinder, wall;
};
std::vector<Pair> flagged_pairs() {
  using Kind = antipode::CollisionPrimitive::Kind;
  antipode::RandomStream random(11);
  std::vector<Pair> pairs(1000);
  for (Pair& p : pairs) {
    p.cylinder.kind = Kind::kCylinder;
    p.cylinder.size_m = Eigen::Vector3d(0.06, 0.273, 0.0);
    p.wall.kind = Kind::kBox;
    p.wall.size_m = Eigen::Vector3d(0.3, 0.3, 0.04);
    const Eigen::Vector3d n =
        Eigen::Vector3d(random.normal(), random.normal(), random.normal()).normalized();
    const double along = std::abs(n.z());
    const double reach = along * 0.1365 + 0.06 * std::sqrt(1.0 - along * along);
    p.wall.X_FrameShape.linear() =
        (Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), n) *
         Eigen::AngleAxisd(random.uniform(0.0, 2 * M_PI), Eigen::Vector3d::UnitZ()))
            .toRotationMatrix();
    p.wall.X_FrameShape.translation() = n * (reach + random.uniform(-0.01, 0.025) + 0.02);
  }
  return pairs;
}
bool fcl_collide(const Pair& p) {
  static const fcl::Cylinderd cylinder(0.06, 0.273);
  static const fcl::Boxd wall(0.3, 0.3, 0.04);
  const fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(&cylinder, p.cylinder.X_FrameShape, &wall, p.wall.X_FrameShape, request, result);
  return result.isCollision();
}
void confirm_pairs(benchmark::State& state, bool quick) {
  const std::vector<Pair> pairs = flagged_pairs();
  std::size_t i = 0, met = 0, undecided = 0, tests = 0;
  for (auto _ : state) {
    const Pair& p = pairs[i];
    auto verdict = antipode::collision::Verdict::kUndecided;
    if (quick) verdict = antipode::collision::quick_test(p.cylinder, p.wall);
    const bool meet = verdict == antipode::collision::Verdict::kUndecided
                          ? (++undecided, fcl_collide(p))
                          : verdict == antipode::collision::Verdict::kMeet;
    met += meet ? 1 : 0;
    i = (i + 1) % pairs.size();
    ++tests;
  }
  state.counters["meet_share"] = double(met) / double(tests);
  state.counters["fcl_share"] = double(undecided) / double(tests);
}
void BM_ConfirmPair_Fcl(benchmark::State& s) { confirm_pairs(s, false); }
void BM_ConfirmPair_QuickThenFcl(benchmark::State& s) { confirm_pairs(s, true); }

BENCHMARK(BM_ConfirmPair_Fcl)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ConfirmPair_QuickThenFcl)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PointsOctree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PointsOctree_PointByPoint)->Unit(benchmark::kMillisecond);
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
BENCHMARK(BM_CheckInCell_Spheres_Batch16_Dense)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckAmongBoxes_Spheres_Batch16)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckAmongBoxes_Spheres_Batch16_Dense)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Batch16_Avx2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CheckInCell_Spheres_Batch16_Baseline)->Unit(benchmark::kMicrosecond);

}  // namespace
