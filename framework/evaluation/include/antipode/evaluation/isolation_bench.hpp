#pragma once
// `antipode bench isolation`: the paper's isolation experiment (section 5.2) in the
// simulated cell - every test object in systematic poses, one attempt per pose and
// variant, through the pick tree's `attempt` tree (docs/cli.md, docs/results.md).

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

struct IsolationBenchOptions {
  std::string objects = "procedural";  ///< "procedural" or a folder of meshes
  std::string procedural_file = "scenes/objects/procedural_test_set.yaml";
  std::vector<std::string> variants;  ///< empty: all five
  int poses = 8;                      ///< systematic poses per object
  int attempts = 0;                   ///< per variant; 0: every object in every pose
  int first = 0;                      ///< the first attempt's number (to rerun one attempt)
  std::uint64_t seed = 1000;          ///< attempt i uses cell seed `seed + i`
  int jobs = 1;                       ///< processes sharing the machine's cores
  std::string report_path;            ///< JSON report ("" = none)
  std::string pictures_dir;           ///< failed attempts drawn here ("" = none)
  /// Each attempt's selection (VARIANT-OBJECT-poseK.json), the cloud it captured (.pcd) and
  /// where the objects lay (-objects.json) written here ("" = none); the tree's
  /// {selection_file}, {cloud_file} and {objects_file} entries.
  std::string selections_dir;
  std::string tree_path = "trees/pick_isolated.yaml";
  std::string noise;                  ///< the cell's sensor noise scale ("" = the tree's)
  std::vector<std::string> held_out;  ///< object names reported apart
  std::vector<std::string> set;       ///< --set overrides of the tree, applied last
  std::string shard;                  ///< "i/n": run only that shard of the attempts ("" = all)
};

/// Plans the attempts (object i % objects, pose (i / objects) % poses), runs them in
/// `jobs` processes (the same results for any number), prints a line per attempt and the
/// tables on standard output, and returns the report: the options, the machine, "summary"
/// (per variant, summarise()) and "attempts" (run_task()'s records). The caller writes it
/// to `report_path` (write_report()); an attempt with outcome "error" measured nothing.
/// Throws antipode::Error for bad options (checked before any attempt runs, the report path
/// included) and BenchStopped when a process stopped the run (its error already printed).
nlohmann::ordered_json run_isolation_bench(const IsolationBenchOptions& options);

/// True when some attempt of an isolation report ended in an error (its tree raised one).
bool has_errors(const nlohmann::ordered_json& isolation_report);

}  // namespace antipode::evaluation
