// Render time per depth view and simulated seconds per wall second of the bullet_cell core.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <vector>

#include "antipode/core/parameters.hpp"
#include "bullet_cell.hpp"
#include "hull_shape.hpp"

namespace antipode::cells {
namespace {

SceneSpec scene(const std::string& yaml) {
  const std::string file = std::string(ANTIPODE_BENCH_SOURCE_DIR) + "/scenes/bench.yaml";
  return parse_scene(Parameters(YAML::Load(yaml), "bench scene", file));
}

const char* kTenPrimitives =
    "box: { inner_size_m: [0.3, 0.3] }\nplacement: pile\n"
    "random_objects: { count: 10, shapes: [box, cylinder, sphere, capsule, ellipsoid] }\n";
const char* kTenYcb =
    "box: { inner_size_m: [0.3, 0.3] }\nplacement: pile\n"
    "random_objects: { count: 10, folder: ../shared/data/objects/ycb }\n";

// One 640 x 480 view (scene upload included); args: noise x 10, threads, YCB (1) or primitives.
void BM_RenderView(benchmark::State& state) {
  const bool ycb = state.range(2) == 1;
  if (ycb && !std::filesystem::exists(std::string(ANTIPODE_BENCH_DATA_DIR) + "/objects/ycb")) {
    state.SkipWithError("shared data not found");
    return;
  }
  CellOptions options;
  options.seed = 7;
  options.sensor.scale = double(state.range(0)) / 10.0;
  options.render_threads = int(state.range(1));
  BulletCell cell(scene(ycb ? kTenYcb : kTenPrimitives), options);
  std::size_t points = 0;
  for (auto _ : state) points = cell.capture({"left"}).size();
  state.counters["points"] = double(points);
  state.counters["objects"] = double(cell.objects().size());
}
BENCHMARK(BM_RenderView)
    ->ArgNames({"noise10", "threads", "ycb"})
    ->Args({0, 1, 0})
    ->Args({10, 1, 0})
    ->Args({10, 2, 0})
    ->Args({0, 1, 1})
    ->Args({10, 1, 1})
    ->Args({10, 2, 1})
    ->Unit(benchmark::kMillisecond);

// Building and settling a pile of ten primitives; the rate counter is simulated s per wall s.
void BM_PileSettle(benchmark::State& state) {
  const SceneSpec spec = scene(kTenPrimitives);
  double simulated = 0.0;
  for (auto _ : state) {
    PhysicsWorld world(PhysicsOptions{});
    MeshCache meshes;
    build_scene(spec, 7, meshes, world);
    simulated += world.time_s();
  }
  state.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_PileSettle)->Unit(benchmark::kMillisecond);

// One successful grasp attempt (approach, close, lift 20 cm, hold 1 s, settle) on a 5 cm
// cylinder standing beside nine other primitives.
void BM_GraspAttempt(benchmark::State& state) {
  CellOptions options;
  options.seed = 7;
  const SceneSpec spec = scene(
      "placement: packed\nregion: { min_m: [0.80, -0.30], max_m: [0.88, 0.0] }\n"
      "objects:\n  - { shape: cylinder, size_m: [0.05, 0.1], position_m: [0.65, -0.12] }\n"
      "random_objects: { count: 9, shapes: [box, cylinder, sphere, capsule, ellipsoid] }\n");
  BulletCell cell(spec, options);
  Hand hand;
  hand.X_FrameHand.linear() << 0, 1, 0, 0, 0, -1, -1, 0, 0;  // approach down, close along x
  hand.X_FrameHand.translation() << 0.65, -0.12, spec.table.top_z_m + 0.105;
  double simulated = 0.0;
  int successes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    cell.reset(7);
    const double before = cell.world().time_s();
    state.ResumeTiming();
    successes += cell.execute({hand, HandGeometry{}, {}}).outcome == GraspOutcome::kSuccess ? 1 : 0;
    simulated += cell.world().time_s() - before;
  }
  state.counters["sim_s_per_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["success_share"] =
      benchmark::Counter(double(successes), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_GraspAttempt)->Unit(benchmark::kMillisecond);

// The support mapping GJK and EPA ask a hull for at every step of every contact, for 1,024
// random directions per iteration, on a hull of 100 vertices (points on a 5 cm sphere; a
// decomposed YCB piece has up to 128): arg 0 Bullet's own scan of the hull, 1 the cell's
// HullShape (the same answers, bit for bit).
void BM_HullSupport(benchmark::State& state) {
  std::mt19937 random(3);
  std::normal_distribution<float> g(0.0f, 1.0f);
  TriangleMesh mesh;
  for (int i = 0; i < 100; ++i)
    mesh.vertices.push_back(Eigen::Vector3f(g(random), g(random), g(random)).normalized() * 0.05f);
  const HullShape shape(mesh, 0.001);
  std::vector<btVector3> directions;
  directions.reserve(1024);
  for (int i = 0; i < 1024; ++i) directions.emplace_back(g(random), g(random), g(random));
  const bool simd = state.range(0) == 1;
  for (auto _ : state) {
    for (const btVector3& d : directions) {
      benchmark::DoNotOptimize(
          simd ? shape.localGetSupportingVertexWithoutMargin(d)
               : shape.btConvexHullShape::localGetSupportingVertexWithoutMargin(d));
    }
  }
  state.counters["vertices"] = shape.getNumPoints();
  state.SetItemsProcessed(state.iterations() * std::int64_t(directions.size()));
}
BENCHMARK(BM_HullSupport)->Arg(0)->Arg(1);

}  // namespace
}  // namespace antipode::cells

BENCHMARK_MAIN();
