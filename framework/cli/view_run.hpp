#pragma once
// `antipode view` of a bench run: a clear-the-box report (`antipode bench clutter --report`)
// and the folders its --selections and --pictures options filled, as one scene per cycle.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::cli {

struct RunInputs {
  std::string report_path;     ///< the bench report (JSON)
  std::string selections_dir;  ///< "" = none: cycles without their cloud and hands
  std::string pictures_dir;    ///< "" = none
  double voxel_m = 0.005;      ///< each cycle's cloud thinned to a point per voxel (0: all)
};

/// Appends one scene per cycle to `data["scenes"]` and sets `data["run"]` (docs/viewer.md):
/// per run its seed, summary and why it stopped; per cycle its outcome, failure class, the
/// cell's detail and record, and its scene's index. A cycle's scene holds the cloud the cycle
/// captured (SEL/seed-S-cycle-NN.pcd), its selection (SEL/seed-S-cycle-NN.json) with the
/// executed grasp marked, where the objects lay (SEL/seed-S-cycle-NN-objects.json) and its
/// picture (PIC/seed-S-cycle-NN.png), each when present. Throws antipode::Error naming the
/// file at fault: a report that is not a clear-the-box report, or a malformed file.
void add_run(const RunInputs& inputs, nlohmann::ordered_json& data);

/// True when `document` is a bench report of clear-the-box runs.
bool is_clutter_report(const nlohmann::ordered_json& document);

}  // namespace antipode::cli
