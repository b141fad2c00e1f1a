// Picks isolated random primitives with no classifier ("NC" in the paper): capture one or two
// views, sample hands with the antipodal sampler, execute the best-scoring hand, count outcomes.
//   pick_isolated [trials] [samples] [noise]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "antipode/core/parameters.hpp"
#include "antipode/geometry/sample_hands.hpp"
#include "bullet_cell.hpp"

namespace antipode::cells {
namespace {

// True when the whole hand (its bounding box in the hand frame) is above the table top, at
// the grasp and 10 cm back along the approach where the cell starts it: the cloud is cropped
// above the table, so the sampler cannot see the table.
bool above_table(const Hand& hand, double top_z) {
  const HandGeometry g;
  for (double back : {0.0, 0.1})
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d p(((corner & 1) ? g.depth_m : -0.02) - back,
                              ((corner & 2) ? 0.5 : -0.5) * g.outer_diameter_m,
                              ((corner & 4) ? 0.5 : -0.5) * g.height_m);
      if ((hand.X_FrameHand * p).z() < top_z + 0.003) return false;
    }
  return true;
}

const Hand* best_hand(const HandSet& set, double top_z) {
  const Hand* best = nullptr;
  for (const Hand& hand : set.hands)
    if (hand.rejection == Rejection::kNone && above_table(hand, top_z) &&
        (!best || hand.score > best->score))
      best = &hand;
  return best;
}

HandSamplingOptions sampling(const SceneSpec& scene, std::size_t samples) {
  HandSamplingOptions options;
  const double top = scene.table.top_z_m;
  options.preprocess.workspace =
      AxisBox{Eigen::Vector3f(0.5f, -0.4f, float(top + 0.005)), Eigen::Vector3f(1.0f, 0.15f, 0.3f)};
  options.search.samples = samples;
  options.search.threads = 2;
  return options;
}

void run(const std::vector<std::string>& views, int trials, std::size_t samples, double noise) {
  const SceneSpec scene =
      read_scene(std::string(ANTIPODE_BENCH_SOURCE_DIR) + "/scenes/isolated_procedural.yaml");
  std::map<std::string, int> outcomes;
  const auto start = std::chrono::steady_clock::now();
  for (int trial = 0; trial < trials; ++trial) {
    CellOptions options;
    options.seed = std::uint64_t(trial);
    options.sensor.scale = noise;
    BulletCell cell(scene, options);
    const Cloud cloud = cell.capture(views);
    const HandSet set = sample_hands(cloud, sampling(scene, samples), RandomStream(trial));
    const Hand* hand = best_hand(set, scene.table.top_z_m);
    ++outcomes[hand ? to_string(cell.execute(*hand, {})) : "no hand found"];
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zuV, noise %.1f, %d objects, %zu samples, %.1f s per trial:", views.size(), noise,
              trials, samples, seconds / trials);
  for (const auto& [name, count] : outcomes) std::printf("  %s %d", name.c_str(), count);
  std::printf("  -> success %.1f%%\n", 100.0 * outcomes["success"] / trials);
}

}  // namespace
}  // namespace antipode::cells

int main(int argc, char** argv) {
  const int trials = argc > 1 ? std::atoi(argv[1]) : 20;
  const std::size_t samples = argc > 2 ? std::size_t(std::atoi(argv[2])) : 1000;
  const double noise = argc > 3 ? std::atof(argv[3]) : 1.0;
  antipode::cells::run({"left"}, trials, samples, noise);
  antipode::cells::run({"left", "right"}, trials, samples, noise);
}
