// Classification with the shipped HOG + SVM model (models/hog_svm.model) on table_mug.pcd
// (104,444 points): descriptors and decision values of 4,000 hand hypotheses, and the whole
// detection (file -> hypotheses -> screen -> classified grasps, as trees/detect.yaml runs it),
// and reading the model file.
// Run with
//   classification_bench --benchmark_repetitions=20 --benchmark_report_aggregates_only=true
#include <algorithm>
#include <chrono>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "antipode/core/parameters.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/io/load_cloud.hpp"
#include "antipode/plugin/plugin_host.hpp"

namespace antipode {
namespace {

const std::string kScene = std::string(ANTIPODE_BENCH_DATA_DIR) + "/clouds/table_mug.pcd";
const std::string kModel = ANTIPODE_BENCH_MODEL;

bool have_inputs(benchmark::State& state) {
  for (const std::string& path : {kScene, kModel}) {
    if (!std::filesystem::exists(path)) {
      state.SkipWithError(("not found: " + path).c_str());
      return false;
    }
  }
  return true;
}

HandSamplingOptions detect_sampling(bool keep_all_positions, bool objects = false) {
  HandSamplingOptions options;  // as trees/detect.yaml: 4,000 samples, support plane auto
  options.search.samples = 4000;
  options.search.threads = 2;
  options.search.keep_all_positions = keep_all_positions;
  options.objects = objects ? ObjectMode::kAuto : ObjectMode::kAll;
  return options;
}

// 4,000 hypotheses of table_mug.pcd (every collision-free position kept, to have enough).
const HandSet& four_thousand_hands() {
  static const HandSet set = [] {
    HandSet all = sample_hands(load_cloud(kScene), detect_sampling(true), RandomStream(1));
    all.hands.resize(std::min<std::size_t>(all.hands.size(), 4000));
    return all;
  }();
  return set;
}

const SvmModel& model() {
  static const SvmModel loaded = SvmModel::load(kModel);
  return loaded;
}

// The model's descriptors (argument 1), and the same without the occlusion statistics (0):
// what they add to the time.
void BM_Descriptors4000(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const HandSet& set = four_thousand_hands();
  HandImageOptions options = model().descriptor.image;
  options.occlusion_features = options.occlusion_features && state.range(0) == 1;
  for (auto _ : state) {
    auto d = hand_descriptors(set, set.geometry, options, 2);
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["hands"] = static_cast<double>(set.hands.size());
}
BENCHMARK(BM_Descriptors4000)
    ->ArgName("occlusion")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_SvmDecisions4000(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const HandSet& set = four_thousand_hands();
  const auto descriptors = hand_descriptors(set, set.geometry, model().descriptor.image, 2);
  for (auto _ : state) {
    auto values = model().decision_values(descriptors, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(values.data());
  }
  state.counters["support_vectors"] = static_cast<double>(model().support_vector_count());
}
BENCHMARK(BM_SvmDecisions4000)->Arg(2)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// What the hog_svm classifier does with a hand set: descriptors, then decision values.
void BM_Classify4000(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const HandSet& set = four_thousand_hands();
  for (auto _ : state) {
    const auto descriptors = hand_descriptors(set, set.geometry, model().descriptor.image, 2);
    auto values = model().decision_values(descriptors, 2);
    benchmark::DoNotOptimize(values.data());
  }
}
BENCHMARK(BM_Classify4000)->Unit(benchmark::kMillisecond)->UseRealTime();

// The selector of trees/detect.yaml (cluster_selector, its defaults), loaded as the tree
// loads it.
const GraspSelector& detect_selector() {
  static PluginHost host(std::vector<std::string>{});
  static const std::shared_ptr<GraspSelector> selector = [] {
    host.load_library(std::string(ANTIPODE_BENCH_PLUGIN_DIR) + "/" +
                      plugin_file_name("cluster_selector"));
    const Parameters params(YAML::Load("{}"), "component 'selector'", "detect.yaml");
    return std::dynamic_pointer_cast<GraspSelector>(host.create("cluster_selector", params));
  }();
  return *selector;
}

// The selector's screen of table_mug.pcd's hypotheses (as trees/detect.yaml samples them).
void BM_Screen(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const HandSet set =
      sample_hands(load_cloud(kScene), detect_sampling(false, true), RandomStream(1));
  const GraspSelector& selector = detect_selector();
  std::size_t left = 0;
  for (auto _ : state) {
    const HandSet screened = selector.screen(set, {});
    left = static_cast<std::size_t>(
        std::count_if(screened.hands.begin(), screened.hands.end(),
                      [](const Hand& h) { return h.rejection == Rejection::kNone; }));
  }
  state.counters["hands"] = static_cast<double>(set.hands.size());
  state.counters["left"] = static_cast<double>(left);
}
BENCHMARK(BM_Screen)->Unit(benchmark::kMillisecond)->UseRealTime();

// Milliseconds since `start`, and `start` moved to now: the stage that just ended.
double lap_ms(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - start).count();
  start = now;
  return ms;
}

// Reading the shipped model file: what a one-shot `antipode detect` pays before its tree.
void BM_LoadModel(benchmark::State& state) {
  if (!have_inputs(state)) return;
  for (auto _ : state) benchmark::DoNotOptimize(SvmModel::load(kModel));
}
BENCHMARK(BM_LoadModel)->Unit(benchmark::kMillisecond)->UseRealTime();

// File -> hypotheses (4,000 samples) -> the selector's screen -> classified grasps, 2 threads:
// what trees/detect.yaml does (ScreenHands, then ClassifyHands on the hands left).
// Argument `objects`: 0 samples everything the support leaves (objects: all), 1 finds the
// objects on the support first and samples only them (objects: auto, as trees/detect.yaml).
// Argument `screen`: 1 screens the hypotheses before classifying them (as the tree does), 0
// classifies them all.
// The counters `load_ms`, `sample_ms`, `screen_ms`, `describe_ms` and `svm_ms` are each
// stage's wall time per iteration (the budget of the detection, stage by stage).
void BM_FileToClassifiedGrasps(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const SvmModel& svm = model();
  const bool screen = state.range(1) != 0;
  const GraspSelector& selector = detect_selector();
  std::size_t hands = 0, classified = 0, grasps = 0;
  double load_ms = 0, sample_ms = 0, screen_ms = 0, describe_ms = 0, svm_ms = 0;
  for (auto _ : state) {
    auto start = std::chrono::steady_clock::now();
    const Cloud cloud = load_cloud(kScene);
    load_ms += lap_ms(start);
    HandSet set = sample_hands(cloud, detect_sampling(false, state.range(0) != 0), RandomStream(1));
    sample_ms += lap_ms(start);
    hands = set.hands.size();
    if (screen) {
      set = selector.screen(set, {});
      set.hands.erase(std::remove_if(set.hands.begin(), set.hands.end(),
                                     [](const Hand& h) { return h.rejection != Rejection::kNone; }),
                      set.hands.end());
    }
    screen_ms += lap_ms(start);
    const auto descriptors = hand_descriptors(set, set.geometry, svm.descriptor.image, 2);
    describe_ms += lap_ms(start);
    const auto values = svm.decision_values(descriptors, 2);
    svm_ms += lap_ms(start);
    classified = set.hands.size();
    grasps = static_cast<std::size_t>(
        std::count_if(values.begin(), values.end(), [](double v) { return v >= 0.0; }));
  }
  state.counters["hands"] = static_cast<double>(hands);
  state.counters["classified"] = static_cast<double>(classified);
  state.counters["grasps"] = static_cast<double>(grasps);
  const auto per_iteration = benchmark::Counter::kAvgIterations;
  state.counters["load_ms"] = benchmark::Counter(load_ms, per_iteration);
  state.counters["sample_ms"] = benchmark::Counter(sample_ms, per_iteration);
  state.counters["screen_ms"] = benchmark::Counter(screen_ms, per_iteration);
  state.counters["describe_ms"] = benchmark::Counter(describe_ms, per_iteration);
  state.counters["svm_ms"] = benchmark::Counter(svm_ms, per_iteration);
}
BENCHMARK(BM_FileToClassifiedGrasps)
    ->ArgNames({"objects", "screen"})
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace antipode
