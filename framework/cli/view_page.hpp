#pragma once
// `antipode view`: one self-contained HTML page that shows a cloud and the hands found in it
// in 3D (three.js), with the data embedded: no server, no network (docs/view.md).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::cli {

struct ViewOptions {
  /// A cloud (.pcd or .ply) and, optionally, a grasps file (.json, from `detect --out` or
  /// WriteGrasps) whose hands were found in that cloud.
  std::vector<std::string> inputs;
  std::string out_path = "view.html";
  /// The gripper file the hands are drawn with ("" = Baxter's,
  /// robots/grippers/baxter_electric.yaml).
  std::string gripper_path;
  bool open = false;  ///< open the page in the desktop's browser (xdg-open) when written
};

/// The page's data (docs/view.md): "title", "frame", "cloud" ({"count", "points": base64 of
/// little-endian float32 x, y, z per point}), "gripper" (its geometry, metres) and "hands" (the
/// grasps file's hands, with the fields the page shows). Throws antipode::Error naming the input at fault.
nlohmann::ordered_json view_data(const ViewOptions& options);

/// The page template built with the viewer (viewer/): the installation's
/// share/antipode/viewer/antipode-view.html, else this build tree's. Throws antipode::Error
/// when this antipode was built without Node.js and npm, saying so.
std::string viewer_template_path();

/// `template_html` with `data` embedded where it marks (<!--antipode-data-->). Throws
/// antipode::Error for a template without the mark.
std::string view_page(const std::string& template_html, const nlohmann::ordered_json& data);

}  // namespace antipode::cli
