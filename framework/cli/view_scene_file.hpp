#pragma once
// `antipode view` of a scene file (scenes/*.yaml, docs/cell.md): the scene built by the cell
// plugin as `antipode scene` builds it, seen by every camera, with where its objects lie and
// its table and box.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::cli {

/// The table and box of the scene file `path` as the page draws them (docs/viewer.md):
/// {"table": {"top_z_m", "center_m", "size_m"}, "box": {"center_m", "inner_size_m",
/// "wall_height_m", "floor_z_m"}}, each when the file has it and the defaults of docs/cell.md
/// otherwise for the table; null when the file cannot be read as YAML.
nlohmann::ordered_json fixtures_json(const std::string& path);

/// The scene of the scene file `path` (a cloud of every camera thinned to `voxel_m`, its
/// segments, the objects' poses and the fixtures) built by running trees/scene.yaml with the
/// cell's `scene` set to it. Throws antipode::Error naming the file when the scene cannot be
/// built.
nlohmann::ordered_json scene_file_scene(const std::string& path, double voxel_m);

}  // namespace antipode::cli
