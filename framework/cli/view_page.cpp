#include "view_page.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <vector>

#include "antipode/config.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/io/load_cloud.hpp"
#include "antipode/robot/robot_file.hpp"
#include "view_encode.hpp"
#include "view_run.hpp"
#include "view_scene_file.hpp"
#include "view_segments.hpp"
#include "view_trace.hpp"

namespace antipode::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr const char* kDataMark = "<!--antipode-data-->";

std::string extension_of(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

Json gripper_json(const std::string& path) {
  const GripperFile gripper = read_gripper_file(resolve_shipped(path));
  const HandGeometry& g = gripper.geometry;
  return {{"name", gripper.name},
          {"finger_width_m", g.finger_width_m},
          {"outer_diameter_m", g.outer_diameter_m},
          {"depth_m", g.depth_m},
          {"height_m", g.height_m},
          {"palm_thickness_m", g.palm_thickness_m},
          {"max_aperture_m", g.max_aperture_m}};
}

// The gripper the hands are drawn with: --gripper, else the gripper of the robot a bench
// report ran with (its `robot` file, or a --gripper it was given), else Baxter's.
std::string gripper_path(const ViewOptions& options, const Json& report) {
  if (!options.gripper_path.empty()) return options.gripper_path;
  if (report.contains("gripper") && report["gripper"].contains("file"))
    return report["gripper"]["file"].get<std::string>();
  if (report.contains("robot") && report["robot"].contains("file"))
    return read_robot_file(resolve_shipped(report["robot"]["file"].get<std::string>()))
        .gripper_path;
  return "robots/grippers/baxter_electric.yaml";
}

// The inputs sorted by kind: at most one of each, a grasps file only with a cloud, a report
// with neither.
struct Inputs {
  std::string cloud, grasps, report, trace, scene;
  Json document;  ///< the grasps file's or the report's content, read once
};

const char* kAccepted =
    "a cloud (.pcd, .ply), a grasps file or a bench report (.json), a scene file (.yaml) or a "
    "trace (.jsonl)";

Inputs sort_inputs(const std::vector<std::string>& paths) {
  Inputs in;
  for (const std::string& path : paths) {
    const std::string extension = extension_of(path);
    std::string* slot = nullptr;
    std::string kind;
    if (extension == ".pcd" || extension == ".ply") {
      slot = &in.cloud, kind = "cloud";
    } else if (extension == ".jsonl") {
      slot = &in.trace, kind = "trace";
    } else if (extension == ".yaml" || extension == ".yml") {
      slot = &in.scene, kind = "scene file";
    } else if (extension == ".json") {
      Json document = evaluation::read_json_file(path, "a grasps file or a bench report");
      const bool report = is_run_report(document);
      slot = report ? &in.report : &in.grasps, kind = report ? "report" : "grasps file";
      if (slot->empty()) in.document = std::move(document);
    } else {
      throw Error("view: '" + path + "': not " + kAccepted);
    }
    if (!slot->empty()) {
      std::string message = "view: '" + path + "': a second ";
      message.append(kind).append(" (after '").append(*slot);
      throw Error(message.append("'); give one cloud and at most one grasps file, or one report"));
    }
    *slot = path;
  }
  if (!in.scene.empty() && !(in.cloud.empty() && in.report.empty()))
    throw Error("view: '" + in.scene + "' with '" + (in.cloud.empty() ? in.report : in.cloud) +
                "': a scene file is shown alone (or with a trace)");
  if (!in.report.empty() && !in.cloud.empty())
    throw Error("view: '" + in.cloud + "' with the report '" + in.report +
                "': a report's attempts bring their own clouds (--selections DIR)");
  if (!in.grasps.empty() && in.cloud.empty())
    throw Error("view: give the cloud (.pcd or .ply) the hands of '" + in.grasps +
                "' were found in");
  if (in.cloud.empty() && in.report.empty() && in.trace.empty() && in.scene.empty())
    throw Error(std::string("view: give ") + kAccepted + " to show");
  return in;
}

// One scene: the cloud and, when given, the hands found in it.
Json detection_scene(const Inputs& in) {
  Json scene = {{"name", fs::path(in.cloud).filename().string()}, {"frame", "sensor"}};
  add_cloud(load_cloud(in.cloud), 0.0, scene);
  if (!in.grasps.empty()) {
    const Json& grasps = in.document;
    scene["hands"] = hand_table(grasps, in.grasps);
    if (grasps.contains("frame") && grasps["frame"].is_string()) scene["frame"] = grasps["frame"];
    scene["name"] =
        scene["name"].get<std::string>() + " + " + fs::path(in.grasps).filename().string();
  }
  return scene;
}

}  // namespace

Json view_data(const ViewOptions& options) {
  const Inputs in = sort_inputs(options.inputs);
  if (in.report.empty() && !(options.selections_dir.empty() && options.pictures_dir.empty()))
    throw Error("view: --selections and --pictures go with a bench report");
  Json data = {{"title", ""}, {"gripper", Json()}, {"scenes", Json::array()}};
  data["gripper"] = gripper_json(gripper_path(options, in.report.empty() ? Json() : in.document));
  if (!in.cloud.empty()) {
    data["scenes"].push_back(detection_scene(in));
    data["title"] = data["scenes"][0]["name"];
  }
  if (!in.scene.empty()) {
    data["scenes"].push_back(scene_file_scene(in.scene, options.voxel_m));
    data["title"] = data["scenes"][0]["name"];
  }
  if (!in.report.empty()) {
    add_run({in.report, options.selections_dir, options.pictures_dir, options.voxel_m}, in.document,
            data);
    data["title"] = fs::path(in.report).filename().string();
  }
  if (!in.trace.empty()) {
    data["trace"] = trace_json(in.trace);
    const std::string title = data["title"];
    data["title"] = title + (title.empty() ? "" : " + ") + fs::path(in.trace).filename().string();
  }
  return data;
}

std::string viewer_template_path() {
  const std::string shipped = shipped_data_dir();
  const fs::path installed = fs::path(shipped) / "viewer" / "antipode-view.html";
  if (!shipped.empty() && fs::is_regular_file(installed)) return installed.string();
  std::string built = ANTIPODE_VIEWER_PAGE;
  if (!built.empty() && fs::is_regular_file(built)) return built;
  if (built.empty())
    throw Error(
        "view: this antipode was built without its viewer: Node.js and npm were not "
        "found when it was configured (install them - scripts/packages.txt - and "
        "configure again)");
  throw Error("view: the viewer page '" + built + "' is missing: build the target antipode_viewer");
}

std::string view_page(const std::string& template_html, const Json& data) {
  const std::size_t mark = template_html.find(kDataMark);
  if (mark == std::string::npos)
    throw Error(std::string("view: the viewer page has no ") + kDataMark + " mark");
  // "</" never appears inside the script element: JSON may escape it as "<\/".
  std::string text = data.dump();
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return template_html.substr(0, mark) + "<script id=\"antipode-data\" type=\"application/json\">" +
         text + "</script>" + template_html.substr(mark + std::string(kDataMark).size());
}

}  // namespace antipode::cli
