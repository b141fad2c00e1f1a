#include "view_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/clutter_bench.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "antipode/io/load_cloud.hpp"
#include "view_encode.hpp"
#include "view_scene_file.hpp"
#include "view_segments.hpp"

namespace antipode::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// DIR/STEM + suffix, or "" without DIR.
std::string file_in(const std::string& dir, const std::string& stem, const std::string& suffix) {
  return dir.empty() ? std::string() : (fs::path(dir) / (stem + suffix)).string();
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

// The arm's planned path (WriteArmPath's file): its links' positions at each waypoint.
Json arm_path(const std::string& path) {
  const Json document = evaluation::read_json_file(path, "an arm's path");
  const auto waypoints = document.find("waypoints");
  if (!document.is_object() || waypoints == document.end() || !waypoints->is_array())
    throw Error(path + ": no \"waypoints\" list (WriteArmPath writes one)");
  Json out = {{"links", document.value("links", Json::array())}, {"waypoints", Json::array()}};
  for (const Json& waypoint : *waypoints) {
    if (!waypoint.is_object() || !waypoint.contains("links_m") || !waypoint["links_m"].is_array())
      throw Error(path + ": a waypoint without \"links_m\"");
    out["waypoints"].push_back(waypoint["links_m"]);
  }
  return out;
}

// One attempt's scene from the files whose names start with `stem` (docs/viewer.md).
Json attempt_scene(const RunInputs& in, const std::string& stem, const std::string& name,
                   const Json& attempt) {
  Json scene = {{"name", name}, {"frame", "base"}};
  const std::string objects = file_in(in.selections_dir, stem, "-objects.json");
  if (!objects.empty() && fs::exists(objects)) {
    const Json truth = evaluation::read_json_file(objects, "an attempt's objects");
    if (!truth.contains("objects") || !truth["objects"].is_array())
      throw Error(objects + ": no \"objects\" list (WriteObjects writes one)");
    scene["objects"] = truth["objects"];
  }
  const std::string cloud = file_in(in.selections_dir, stem, ".pcd");
  if (!cloud.empty() && fs::exists(cloud)) {
    Cloud whole = load_cloud(cloud, {std::nullopt, "base"});
    if (auto masks = load_view_masks(cloud); !masks.empty()) whole.view_masks = std::move(masks);
    add_cloud(around_objects(whole, scene.value("objects", Json())), in.voxel_m, scene);
  }
  const std::string selection = file_in(in.selections_dir, stem, ".json");
  if (!selection.empty() && fs::exists(selection)) {
    const Json grasps = evaluation::read_json_file(selection, "an attempt's selection");
    scene["hands"] = hand_table(grasps, selection);
    scene["executed"] = executed_index(grasps, attempt);
    if (attempt.contains("record"))
      scene["attempt"] = {{"outcome", attempt.value("outcome", "")},
                          {"reason", attempt.value("reason", "")},
                          {"record", attempt["record"]}};
  }
  const std::string path = file_in(in.selections_dir, stem, "-path.json");
  if (!path.empty() && fs::exists(path)) scene["path"] = arm_path(path);
  const std::string picture = file_in(in.pictures_dir, stem, ".png");
  if (!picture.empty() && fs::exists(picture)) scene["picture"] = png_data_uri(picture);
  return scene;
}

// A report's attempts in the page's groups: a clear-the-box run per seed, its cycles in
// order; an isolation bench per variant, its attempts in order.
struct Attempt {
  std::string stem;   ///< the file names its bench gave it, without extension
  std::string title;  ///< how the list names it
  Json record;        ///< the report's entry
};
struct Group {
  std::string title;
  std::vector<Attempt> attempts;
};

std::vector<Group> clutter_groups(const Json& report) {
  std::vector<Group> groups;
  for (const Json& run : report["run_records"]) {
    const auto seed_number = run.value("seed", std::uint64_t(0));
    const int replicate = run.value("replicate", 0);
    std::string seed = std::to_string(seed_number);
    const std::string prefix = evaluation::clutter_run_prefix(seed_number, replicate);
    if (replicate > 0) seed += " (replicate " + std::to_string(replicate) + ")";
    Group group{
        "seed " + seed + ": " + run.value("summary", "") + " (" + run.value("stop", "") + ")", {}};
    const Json cycles = run.value("cycles", Json::array());
    for (std::size_t k = 0; k < cycles.size(); ++k) {
      char number[24];
      std::snprintf(number, sizeof number, "%02zu", k + 1);
      group.attempts.push_back({prefix + "cycle-" + number,
                                "seed " + seed + ", cycle " + std::to_string(k + 1), cycles[k]});
    }
    groups.push_back(std::move(group));
  }
  return groups;
}

std::vector<Group> isolation_groups(const Json& report) {
  std::vector<Group> groups;
  std::map<std::string, std::size_t> group_of;  // variant -> its group, in order of appearance
  for (const Json& attempt : report["attempts"]) {
    const std::string variant = attempt.value("variant", "");
    if (group_of.emplace(variant, groups.size()).second) {
      const Json summary = report.value("summary", Json::object()).value(variant, Json::object());
      groups.push_back({variant + ": " + std::to_string(summary.value("successes", 0)) + " of " +
                            std::to_string(summary.value("attempts", 0)) + " attempts succeeded",
                        {}});
    }
    const std::string object = attempt.value("object", "");
    const std::string pose = std::to_string(attempt.value("pose", 0));
    std::string stem = variant;
    stem.append("-").append(object).append("-pose").append(pose);
    groups[group_of[variant]].attempts.push_back({stem, object + ", pose ", attempt});
    groups[group_of[variant]].attempts.back().title += pose;
  }
  return groups;
}

bool is_isolation_report(const Json& document) {
  return document.is_object() && document.value("bench", "") == "isolation" &&
         document.contains("attempts") && document["attempts"].is_array();
}

// The table and box of the scene the report's tree gave its cell (null when the tree or the
// scene cannot be read: the page then draws none).
Json report_fixtures(const Json& report) {
  try {
    const YAML::Node tree = YAML::LoadFile(report.value("tree", ""));
    const YAML::Node scene = tree["components"]["cell"]["scene"];
    return scene && scene.IsScalar() ? fixtures_json(scene.as<std::string>()) : Json();
  } catch (const YAML::Exception&) {
    return nullptr;
  }
}

}  // namespace

bool is_run_report(const Json& document) {
  return is_isolation_report(document) ||
         (document.is_object() && document.value("bench", "") == "clutter" &&
          document.contains("run_records") && document["run_records"].is_array());
}

void add_run(const RunInputs& in, const Json& report, Json& data) {
  if (!is_run_report(report))
    throw Error(in.report_path +
                ": not a report of `antipode bench clutter` or `bench isolation` (no "
                "\"run_records\" or \"attempts\")");
  for (const std::string& dir : {in.selections_dir, in.pictures_dir})
    if (!dir.empty() && !fs::is_directory(dir)) throw Error("view: '" + dir + "' is not a folder");
  Json runs = Json::array();
  const std::size_t first_scene = data["scenes"].size();
  for (const Group& group :
       is_isolation_report(report) ? isolation_groups(report) : clutter_groups(report)) {
    Json run = {{"title", group.title}, {"cycles", Json::array()}};
    for (const Attempt& attempt : group.attempts) {
      const Json& r = attempt.record;
      Json entry = {{"title", attempt.title},
                    {"outcome", r.value("outcome", "")},
                    {"reason", r.value("reason", "")},
                    {"detail", r.value("detail", "")},
                    {"scene", data["scenes"].size()}};
      if (r.contains("record")) entry["record"] = r["record"];
      data["scenes"].push_back(attempt_scene(in, attempt.stem, attempt.title, r));
      run["cycles"].push_back(std::move(entry));
    }
    runs.push_back(std::move(run));
  }
  const Json fixtures = report_fixtures(report);
  for (std::size_t k = first_scene; k < data["scenes"].size(); ++k)
    data["scenes"][k]["fixtures"] = fixtures;
  data["run"] = {{"report", fs::path(in.report_path).filename().string()},
                 {"bench", report.value("bench", "")},
                 {"summary", report.value("summary", Json::object())},
                 {"runs", runs}};
}

}  // namespace antipode::cli
