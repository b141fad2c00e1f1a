#pragma once
// `antipode bench clutter`: the paper's dense-clutter experiment (section 5.3) in the
// simulated cell - seeded clear-the-box runs of trees/clear_box.yaml, tallied as grasp
// success (successes / attempts), objects removed and the failure breakdown (docs/cli.md,
// docs/results.md).

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

struct ClutterBenchOptions {
  std::string objects = "procedural";  ///< "procedural" (the scene's shapes) or a mesh folder
  int runs = 10;
  std::string protocol = "paper";  ///< "paper", "vgn-pile" or "vgn-packed" (clutter_protocols.hpp)
  int objects_per_run = 0;         ///< 0: the protocol's (10; VGN's 5)
  std::uint64_t seed = 2000;       ///< run i uses cell seed `seed + i`
  /// Each run this many times: replicate 0 as the tree is, replicate r > 0 with
  /// kReplicateNoiseM of execution noise drawn with seed r (the cell's `execution_noise_m` and
  /// `execution_seed`), so that runs that diverge from the first contact that differs show how
  /// far one draw of the runs can be trusted.
  int replicates = 1;
  int jobs = 1;             ///< processes sharing the machine's cores
  std::string report_path;  ///< JSON report ("" = none)
  std::string tree_path;    ///< "": the protocol's (trees/clear_box.yaml; trees/vgn_round.yaml)
  std::string noise;        ///< the cell's sensor noise scale ("" = the tree's)
  std::vector<std::string> set;  ///< --set overrides of the tree, applied last
  std::string shard;             ///< "i/n": run only that shard of the runs ("" = all)
  std::string pictures_dir;      ///< failed attempts drawn as seed-S-cycle-NN.png ("" = none)
  /// Each cycle's selection written as seed-S-cycle-NN.json ("" = none).
  std::string selections_dir;
  /// A gripper file (antipode/io/gripper_file.hpp) for the sampler's `hand`, whose apertures
  /// also set which objects left count as holdable ("" = the tree's: its robot file's gripper,
  /// or Baxter's range without one).
  std::string gripper_path;
};

/// The execution noise of the replicates after the first (metres, standard deviation per axis):
/// a tenth of a millimetre, far below an arm's repeatability, enough to send a run elsewhere.
constexpr double kReplicateNoiseM = 0.0001;

/// The file-name prefix of run `seed`'s replicate `replicate` (pictures, selections):
/// "seed-S-", or "seed-S-replicate-R-" for replicate R > 0.
std::string clutter_run_prefix(std::uint64_t seed, int replicate);

/// Runs the clear-the-box runs in `jobs` processes (the same results for any number), prints
/// one line per run and the summary on standard output, and returns the report: the options,
/// the machine, "summary" (summarise_clutter()) and "run_records". The caller writes it to
/// `report_path` (write_report()); a summary with "errors" above 0 has runs that measured
/// nothing. Throws antipode::Error for bad options (checked before any run, the report path
/// included) and BenchStopped when a process stopped the bench (its error already printed).
nlohmann::ordered_json run_clutter_bench(const ClutterBenchOptions& options);

/// The report's "summary" over run records: runs, attempts, successes, objects, removed,
/// lost, success_rate and removed_rate with 95% intervals (also "by_replicate" when the records
/// are of several replicates: each one's runs, attempts, successes, objects, removed, lost and
/// rates), cycles, no_grasp (cycles that found
/// no grasp), reasons (failure classes of the attempts), paper_classes (the paper's groups:
/// perception, dropped, collision, reach, other), stops and the median seconds of a cycle
/// and of a run; with the cell's ground truth also left, left_graspable,
/// removed_of_graspable_rate and graspable_width_m (the holdable range [min, max]).
nlohmann::ordered_json summarise_clutter(const nlohmann::ordered_json& runs);

/// The 95% intervals that resample whole runs (run_bootstrap.hpp) over the run records that
/// ended without an error, the replicates of a seed taken together as one run: {"runs": how many,
/// "success": [lo, hi]} for successes / attempts and "removed": [lo, hi] for removed / objects over
/// the runs whose cell counted its objects, each when at least two runs contribute. Attempts within
/// a run share its scene, so these are the better guide to noise within one draw; the replicates
/// show the noise between draws.
nlohmann::ordered_json between_runs_intervals(const nlohmann::ordered_json& runs);

/// Prints a clutter report's summary as the bench does after its runs, beside the published
/// figures of `protocol` ("paper", "vgn-pile", "vgn-packed").
void print_clutter_summary(std::ostream& out, const nlohmann::ordered_json& summary,
                           const std::string& protocol);

/// The widths [min, max] (metres) a gripper with these apertures holds, as the benches count
/// objects: the apertures rounded inwards to whole centimetres (Baxter's 2.9-7.2 cm give the
/// paper's 3-7 cm).
std::pair<double, double> graspable_width_m(double min_aperture_m, double max_aperture_m);

/// A clutter summary's holdable range: its graspable_width_m, or Baxter's for reports that
/// have none.
std::pair<double, double> summary_graspable_width_m(const nlohmann::ordered_json& summary);

}  // namespace antipode::evaluation
