// Classification with the shipped HOG + SVM model (models/hog_svm.model) on table_mug.pcd
// (104,444 points): descriptors and decision values of 4,000 hand hypotheses, and the whole
// detection (file -> hypotheses -> classified grasps, as trees/detect.yaml runs it). Run with
//   classification_bench --benchmark_repetitions=20 --benchmark_report_aggregates_only=true
#include <algorithm>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "antipode/geometry/sample_hands.hpp"
#include "antipode/grasp/hand_image.hpp"
#include "antipode/grasp/svm_model.hpp"
#include "antipode/io/load_cloud.hpp"

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

// File -> hypotheses (4,000 samples) -> classified grasps, 2 threads.
void BM_FileToClassifiedGrasps(benchmark::State& state) {
  if (!have_inputs(state)) return;
  const SvmModel& svm = model();
  std::size_t hands = 0, grasps = 0;
  for (auto _ : state) {
    const HandSet set = sample_hands(load_cloud(kScene),
                                     detect_sampling(false, state.range(0) != 0), RandomStream(1));
    const auto values =
        svm.decision_values(hand_descriptors(set, set.geometry, svm.descriptor.image, 2), 2);
    hands = set.hands.size();
    grasps = static_cast<std::size_t>(
        std::count_if(values.begin(), values.end(), [](double v) { return v >= 0.0; }));
  }
  state.counters["hands"] = static_cast<double>(hands);
  state.counters["grasps"] = static_cast<double>(grasps);
}
// Argument: 0 samples everything the support leaves (objects: all), 1 finds the objects on
// the support first and samples only them (objects: auto, as trees/detect.yaml).
BENCHMARK(BM_FileToClassifiedGrasps)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace antipode
