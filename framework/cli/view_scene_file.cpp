#include "view_scene_file.hpp"

#include <filesystem>

#include <yaml-cpp/yaml.h>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/json_file.hpp"
#include "antipode/evaluation/scratch_folder.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/io/load_cloud.hpp"
#include "view_segments.hpp"

namespace antipode::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json numbers(const YAML::Node& node, std::size_t size, Json otherwise) {
  if (!node || !node.IsSequence() || node.size() != size) return otherwise;
  Json out = Json::array();
  for (const YAML::Node& v : node) out.push_back(v.as<double>());
  return out;
}

}  // namespace

Json fixtures_json(const std::string& path) {
  YAML::Node scene;
  try {
    scene = YAML::LoadFile(resolve_shipped(path));
    const YAML::Node table = scene["table"];
    const double top = table && table["top_z_m"] ? table["top_z_m"].as<double>() : -0.295;
    Json out = {
        {"table",
         {{"top_z_m", top},
          {"center_m", numbers(table ? table["center_m"] : YAML::Node(), 2, {0.725, -0.135})},
          {"size_m", numbers(table ? table["size_m"] : YAML::Node(), 2, {0.9, 1.0})}}}};
    if (const YAML::Node box = scene["box"]) {
      out["box"] = {
          {"center_m", numbers(box["center_m"], 2, {0.725, -0.135})},
          {"inner_size_m", numbers(box["inner_size_m"], 2, {0.3, 0.3})},
          {"wall_height_m", box["wall_height_m"] ? box["wall_height_m"].as<double>() : 0.06},
          {"floor_z_m", top}};
    }
    return out;
  } catch (const YAML::Exception&) {
    return nullptr;  // the scene file is checked where it is used; the page just lacks them
  }
}

Json scene_file_scene(const std::string& path, double voxel_m) {
  const evaluation::ScratchFolder scratch("view");  // the scene tree's files, removed after
  const std::string tree = resolve_shipped("trees/scene.yaml");
  const std::vector<std::string> entries = {
      "cell.scene='" + path + "'",
      "image_file=", "grasps_file=", "cloud_file=" + scratch.file("cloud.pcd"),
      "objects_file=" + scratch.file("objects.json")};
  const evaluation::TreeRunSettings settings;
  evaluation::Session session = evaluation::open_session_for(tree, entries, settings);
  bt::Tree run = evaluation::load_tree_for(session, tree, entries, settings);
  run.set_log_sink([](const bt::Node&, const std::string&) {});
  if (run.tick_while_running() != bt::Status::kSuccess)
    throw Error("view: '" + path + "': the scene could not be built and seen (antipode scene " +
                path + " says why)");
  Json scene = {{"name", fs::path(path).filename().string()}, {"frame", "base"}};
  scene["objects"] =
      evaluation::read_json_file(scratch.file("objects.json"), "the objects")["objects"];
  add_cloud(load_cloud(scratch.file("cloud.pcd"), {std::nullopt, "base"}), voxel_m, scene);
  scene["fixtures"] = fixtures_json(path);
  return scene;
}

}  // namespace antipode::cli
