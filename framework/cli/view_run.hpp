#pragma once
// `antipode view` of a bench run: a clear-the-box or isolation report (`antipode bench clutter
// --report`, `bench isolation --report`) and the folders its --selections and --pictures
// options filled, as one scene per attempt.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::cli {

struct RunInputs {
  std::string report_path;     ///< the bench report (JSON)
  std::string selections_dir;  ///< "" = none: cycles without their cloud and hands
  std::string pictures_dir;    ///< "" = none
  double voxel_m = 0.005;      ///< each cycle's cloud thinned to a point per voxel (0: all)
};

/// For the bench report `report` (read from inputs.report_path): appends one scene per attempt (a
/// clear-the-box cycle, an isolation attempt) to `data["scenes"]` and sets `data["run"]`
/// (docs/viewer.md): the attempts in groups (a clear-the-box run per seed, an isolation variant),
/// each with its outcome, failure class, the cell's detail and record, and its scene's index. An
/// attempt's scene holds the cloud it captured (SEL/STEM.pcd), its selection (SEL/STEM.json) with
/// the executed grasp marked, where the objects lay (SEL/STEM-objects.json), the arm's planned path
/// (SEL/STEM-path.json) and its picture (PIC/STEM.png), each when present; STEM is seed-S-cycle-NN
/// for a cycle, VARIANT-OBJECT-poseK for an isolation attempt. Throws antipode::Error naming the
/// file at fault: a report of another kind, or a malformed file.
void add_run(const RunInputs& inputs, const nlohmann::ordered_json& report,
             nlohmann::ordered_json& data);

/// True when `document` is a report of clear-the-box runs or of an isolation bench.
bool is_run_report(const nlohmann::ordered_json& document);

}  // namespace antipode::cli
