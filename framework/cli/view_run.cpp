#include "view_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/io/load_cloud.hpp"
#include "view_encode.hpp"

namespace antipode::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// DIR/seed-S-cycle-NN + suffix, the names clear_box.yaml's prefixes give ("" without DIR).
std::string cycle_file(const std::string& dir, std::uint64_t seed, std::size_t cycle,
                       const std::string& suffix) {
  if (dir.empty()) return {};
  char number[24];
  std::snprintf(number, sizeof number, "%02zu", cycle);
  return (fs::path(dir) / ("seed-" + std::to_string(seed) + "-cycle-" + number + suffix)).string();
}

std::string png_data_uri(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in) throw Error(path + ": cannot read the picture");
  const std::string png = bytes.str();
  return "data:image/png;base64," + base64(png.data(), png.size());
}

// The index of the hand of `table` at the executed grasp's position (the selection holds
// it), or -1.
int executed_index(const Json& selection, const Json& cycle) {
  const auto hand = cycle.find("hand");
  if (hand == cycle.end() || !hand->is_object()) return -1;
  const Json position = hand->value("position_m", Json());
  if (!position.is_array() || position.size() != 3 ||
      !std::all_of(position.begin(), position.end(), [](const Json& v) { return v.is_number(); }))
    return -1;
  const Json& hands = selection["hands"];
  for (std::size_t i = 0; i < hands.size(); ++i) {
    double d = 0.0;
    for (int k = 0; k < 3; ++k)
      d += std::fabs(hands[i]["position_m"][k].get<double>() - position[k].get<double>());
    const auto rank = hands[i].find("rank");
    if (d < 1e-6 && rank != hands[i].end() && rank->is_number()) return int(i);
  }
  return -1;
}

// The region a cycle's page shows: its objects' positions grown by kAround_m (the box and its
// walls, a hand's length above), or everything when the cell gave no objects. A cell's views
// see the whole table and more: 400,000 points a cycle, most of them far from any object.
constexpr float kAround_m = 0.15f;

Cloud around_objects(const Cloud& cloud, const Json& objects) {
  if (!objects.is_array() || objects.empty()) return cloud;
  AxisBox box{Eigen::Vector3f::Constant(1e30f), Eigen::Vector3f::Constant(-1e30f)};
  for (const Json& object : objects) {
    const Json& p = object.value("position_m", Json());
    if (!p.is_array() || p.size() != 3) continue;
    const Eigen::Vector3f at(p[0].get<float>(), p[1].get<float>(), p[2].get<float>());
    box.min_m = box.min_m.cwiseMin(at - Eigen::Vector3f::Constant(kAround_m));
    box.max_m = box.max_m.cwiseMax(at + Eigen::Vector3f::Constant(kAround_m));
  }
  return box.min_m.x() <= box.max_m.x() ? crop(cloud, box) : cloud;
}

Json cycle_scene(const RunInputs& in, std::uint64_t seed, std::size_t number, const Json& cycle) {
  Json scene = {{"name", "seed " + std::to_string(seed) + ", cycle " + std::to_string(number)},
                {"frame", "base"}};
  const std::string objects = cycle_file(in.selections_dir, seed, number, "-objects.json");
  if (!objects.empty() && fs::exists(objects)) {
    const Json truth = evaluation::read_json_file(objects, "a cycle's objects");
    if (!truth.contains("objects") || !truth["objects"].is_array())
      throw Error(objects + ": no \"objects\" list (WriteObjects writes one)");
    scene["objects"] = truth["objects"];
  }
  const std::string cloud = cycle_file(in.selections_dir, seed, number, ".pcd");
  if (!cloud.empty() && fs::exists(cloud)) {
    const Cloud whole = load_cloud(cloud, {std::nullopt, "base"});
    scene["cloud"] = cloud_json(around_objects(whole, scene.value("objects", Json())), in.voxel_m);
  }
  const std::string selection = cycle_file(in.selections_dir, seed, number, ".json");
  if (!selection.empty() && fs::exists(selection)) {
    const Json grasps = evaluation::read_json_file(selection, "a cycle's selection");
    scene["hands"] = hand_table(grasps, selection);
    scene["executed"] = executed_index(grasps, cycle);
  }
  const std::string picture = cycle_file(in.pictures_dir, seed, number, ".png");
  if (!picture.empty() && fs::exists(picture)) scene["picture"] = png_data_uri(picture);
  return scene;
}

}  // namespace

bool is_clutter_report(const Json& document) {
  return document.is_object() && document.value("bench", "") == "clutter" &&
         document.contains("run_records");
}

void add_run(const RunInputs& in, Json& data) {
  const Json report = evaluation::read_json_file(in.report_path, "a bench report");
  if (!is_clutter_report(report) || !report["run_records"].is_array())
    throw Error(in.report_path +
                ": not a clear-the-box report (no \"run_records\" of bench \"clutter\"; "
                "`antipode bench clutter --report` writes one)");
  for (const std::string& dir : {in.selections_dir, in.pictures_dir})
    if (!dir.empty() && !fs::is_directory(dir)) throw Error("view: '" + dir + "' is not a folder");
  Json runs = Json::array();
  for (const Json& record : report["run_records"]) {
    const std::uint64_t seed = record.value("seed", std::uint64_t(0));
    Json run = {{"seed", seed},
                {"summary", record.value("summary", "")},
                {"stop", record.value("stop", "")},
                {"cycles", Json::array()}};
    const Json cycles = record.value("cycles", Json::array());
    for (std::size_t k = 0; k < cycles.size(); ++k) {
      const Json& cycle = cycles[k];
      Json entry = {{"outcome", cycle.value("outcome", "")},
                    {"reason", cycle.value("reason", "")},
                    {"detail", cycle.value("detail", "")},
                    {"scene", data["scenes"].size()}};
      if (cycle.contains("record")) entry["record"] = cycle["record"];
      data["scenes"].push_back(cycle_scene(in, seed, k + 1, cycle));
      run["cycles"].push_back(std::move(entry));
    }
    runs.push_back(std::move(run));
  }
  data["run"] = {{"report", fs::path(in.report_path).filename().string()},
                 {"summary", report.value("summary", Json::object())},
                 {"runs", runs}};
}

}  // namespace antipode::cli
