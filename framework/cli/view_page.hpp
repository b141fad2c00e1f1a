#pragma once
// `antipode view`: one self-contained HTML page that shows a cloud and the hands found in it
// in 3D (three.js), with the data embedded: no server, no network (docs/viewer.md).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::cli {

struct ViewOptions {
  /// What to show (docs/viewer.md): a cloud (.pcd, .ply) with at most one grasps file (.json from
  /// `detect --out` or WriteGrasps) found in it; or a clear-the-box report (.json from `bench
  /// clutter --report`); and, with either or alone, a trace of a tree run (.jsonl from `run
  /// --trace`).
  std::vector<std::string> inputs;
  std::string out_path = "view.html";
  /// The gripper file the hands are drawn with ("" = a bench report's own: its --gripper or
  /// its robot file's; else Baxter's, robots/grippers/baxter_electric.yaml).
  std::string gripper_path;
  /// With a report: the folders its bench's --selections and --pictures filled ("" = none).
  std::string selections_dir;
  std::string pictures_dir;
  /// With a report: each cycle's cloud thinned to one point per voxel of this edge (0 = all).
  double voxel_m = 0.005;
  bool open = false;  ///< open the page in the desktop's browser (xdg-open) when written
};

/// The page's data (docs/viewer.md, "What is in the page"): "title", "gripper" (its geometry,
/// metres), "scenes" (each a cloud, hands, objects and what happened there), and "run" (a
/// report's runs and cycles) and "trace" (a tree run's nodes and status changes) when given.
/// Throws antipode::Error naming the input at fault.
nlohmann::ordered_json view_data(const ViewOptions& options);

/// The page template built with the viewer (viewer/): the installation's
/// share/antipode/viewer/antipode-view.html, else this build tree's. Throws antipode::Error
/// when this antipode was built without Node.js and npm, saying so.
std::string viewer_template_path();

/// `template_html` with `data` embedded where it marks (<!--antipode-data-->). Throws
/// antipode::Error for a template without the mark.
std::string view_page(const std::string& template_html, const nlohmann::ordered_json& data);

}  // namespace antipode::cli
