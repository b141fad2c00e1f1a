#pragma once
// Outcome data: grasp trials in the simulated cell, labelled by whether they held
// (`antipode outcomes`, docs/training.md "Outcome labels"). The tree (trees/outcomes.yaml) runs
// once per scene seed and writes that scene's trial files into a folder; this engine chooses
// the seeds (a shard's, those not done yet), runs them in processes, and reports throughput.

#include <cstdint>
#include <string>
#include <vector>

namespace antipode::evaluation {

struct OutcomeDataOptions {
  std::string tree_path = "trees/outcomes.yaml";
  std::string out_dir;                ///< the trial files' folder
  int scenes = 100;                   ///< seeds first_seed .. first_seed + scenes - 1
  std::uint64_t first_seed = 100000;  ///< far from the benches' seeds (2000-2019)
  std::string shard;                  ///< "i/n": every n-th seed from the i-th; "" = all
  int jobs = 1;                       ///< processes
  std::vector<std::string> set;       ///< the user's --set entries, applied last
};

/// `antipode outcomes`: runs the tree (with the entries `seed`, `records_file` and `data_file`)
/// for every seed of the shard whose record file is not in
/// the folder yet (so a killed run resumes where it stopped), prints one line per scene and
/// then the trials, the share that held and the throughput in trials per CPU-second. The same
/// seeds give the same files for any number of processes or shards. Returns the scenes that
/// ended in an error (printed above; running again retries them). Throws antipode::Error for
/// bad options and BenchStopped when a process stopped the run (its error already printed).
int run_outcome_data(const OutcomeDataOptions& options);

/// "scene-000123.json": the file whose presence marks seed 123 done (SaveTrials writes it last).
std::string outcome_records_name(std::uint64_t seed);
/// "scene-000123.data": the descriptors of seed 123's trials, written before its record file.
std::string outcome_data_name(std::uint64_t seed);

}  // namespace antipode::evaluation
