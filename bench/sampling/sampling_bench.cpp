// The sampling stage on table_mug.pcd (104,444 points): the whole run from file to hand
// hypotheses (4,000 samples, 2 threads) and its stages. Run with, e.g.,
//   sampling_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <filesystem>

#include <benchmark/benchmark.h>

#include "antipode/geometry/hand_search.hpp"
#include "antipode/geometry/local_frame.hpp"
#include "antipode/geometry/point_index.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/geometry/support_plane.hpp"
#include "antipode/io/load_cloud.hpp"
#include "bench_data.hpp"
#include "cloud_select.hpp"

namespace antipode {
namespace {

const std::string kScene = bench::shared_cloud("table_mug.pcd");

bool have_scene(benchmark::State& state) {
  if (std::filesystem::exists(kScene)) return true;
  state.SkipWithError(("shared cloud not found: " + kScene).c_str());
  return false;
}

HandSearchParameters paper_parameters(int threads) {
  HandSearchParameters parameters;  // 3 cm frames, 8 orientations x 20 positions
  parameters.samples = 4000;
  parameters.threads = threads;
  return parameters;
}

// File -> preprocessed cloud -> hand hypotheses.
void BM_FileToHypotheses(benchmark::State& state) {
  if (!have_scene(state)) return;
  const HandSearchParameters parameters = paper_parameters(static_cast<int>(state.range(0)));
  std::size_t hands = 0;
  for (auto _ : state) {
    const Cloud cloud = preprocess(load_cloud(kScene), PreprocessOptions{});
    hands = search_hands(cloud, parameters, RandomStream(1)).hands.size();
    benchmark::DoNotOptimize(hands);
  }
  state.counters["hands"] = static_cast<double>(hands);
}
BENCHMARK(BM_FileToHypotheses)->Arg(2)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Load(benchmark::State& state) {
  if (!have_scene(state)) return;
  for (auto _ : state) benchmark::DoNotOptimize(load_cloud(kScene).size());
}
BENCHMARK(BM_Load)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Voxelize(benchmark::State& state) {
  if (!have_scene(state)) return;
  const Cloud raw = load_cloud(kScene);
  std::size_t points = 0;
  for (auto _ : state) {
    points = preprocess(raw, PreprocessOptions{}).size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_Voxelize)->Unit(benchmark::kMillisecond)->UseRealTime();

// KD-tree build and 4,000 Darboux frames (3 cm Taubin fits), one thread.
void BM_Frames(benchmark::State& state) {
  if (!have_scene(state)) return;
  const Cloud cloud = preprocess(load_cloud(kScene), PreprocessOptions{});
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / 4000);
  std::vector<std::int32_t> neighbours;
  for (auto _ : state) {
    const PointIndex index(cloud.points_m);
    int usable = 0;
    for (std::size_t i = 0, n = 0; i < cloud.size() && n < 4000; i += stride, ++n) {
      const Eigen::Vector3f& p = cloud.points_m[i];
      index.radius_search(p, 0.03f, neighbours);
      usable += estimate_local_frame(cloud.points_m, neighbours, p, -p.normalized()).usable();
    }
    benchmark::DoNotOptimize(usable);
  }
}
BENCHMARK(BM_Frames)->Unit(benchmark::kMillisecond)->UseRealTime();

// The hand search alone (frames included) on the preprocessed cloud.
void BM_HandSearch(benchmark::State& state) {
  if (!have_scene(state)) return;
  const Cloud cloud = preprocess(load_cloud(kScene), PreprocessOptions{});
  const HandSearchParameters parameters = paper_parameters(static_cast<int>(state.range(0)));
  HandSearchStats stats;
  for (auto _ : state) {
    HandSearchResult result = search_hands(cloud, parameters, RandomStream(1));
    stats = result.stats;
    benchmark::DoNotOptimize(result.hands.data());
  }
  state.counters["hands"] = static_cast<double>(stats.hands);
  state.counters["poses"] = static_cast<double>(stats.poses);
  state.counters["samples"] = static_cast<double>(stats.samples);
  state.counters["on_support"] = static_cast<double>(stats.on_support);
}
BENCHMARK(BM_HandSearch)->Arg(2)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// Finding the support plane (the table) on the preprocessed cloud.
void BM_SupportPlane(benchmark::State& state) {
  if (!have_scene(state)) return;
  const Cloud cloud = preprocess(load_cloud(kScene), PreprocessOptions{});
  std::size_t inliers = 0;
  for (auto _ : state) {
    const auto plane = find_support_plane(cloud, Eigen::Vector3f::Zero(), SupportPlaneOptions{},
                                          RandomStream(1).derive(0xFFFFFFFFFFFFull));
    inliers = plane ? plane->inliers : 0;
    benchmark::DoNotOptimize(inliers);
  }
  state.counters["inliers"] = static_cast<double>(inliers);
}
BENCHMARK(BM_SupportPlane)->Unit(benchmark::kMillisecond)->UseRealTime();

// The scene stage of `objects: auto` (trees/detect.yaml): candidate planes, the support and
// the objects on it, on the preprocessed cloud.
void BM_SceneLayout(benchmark::State& state) {
  if (!have_scene(state)) return;
  const Cloud cloud = preprocess(load_cloud(kScene), PreprocessOptions{});
  const Eigen::Vector3f sensor = geometry::sensor_position(cloud);  // as sample_hands finds it
  std::size_t objects = 0;
  for (auto _ : state) {
    const SceneLayout layout = find_scene_layout(cloud, sensor, SceneOptions{}, RandomStream(1));
    objects = layout.objects.size();
    benchmark::DoNotOptimize(layout.object_of_point.data());
  }
  state.counters["objects"] = static_cast<double>(objects);
}
BENCHMARK(BM_SceneLayout)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace antipode
