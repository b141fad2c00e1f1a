#pragma once
// A scene description as read from YAML (grammar in docs/cell.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "camera.hpp"
#include "procedural_objects.hpp"

namespace antipode {
class Parameters;
}

namespace antipode::cells {

struct TableSpec {
  double top_z_m = -0.295;  ///< Baxter's base frame is 0.924 m above the floor
  Eigen::Vector2d center_m{0.725, -0.135};
  Eigen::Vector2d size_m{0.9, 1.0};
  double friction = 0.8;
};

/// The shallow box that clutter is dumped into (its floor is the table).
struct BoxSpec {
  bool present = false;
  Eigen::Vector2d center_m{0.725, -0.135};
  Eigen::Vector2d inner_size_m{0.3, 0.3};
  double wall_height_m = 0.06;
  double wall_thickness_m = 0.01;
  /// Lifted away once a pile has settled, as in VGN's "pile" scenes: the objects spread.
  bool removed_after_drop = false;
  /// A pile's object that comes to rest outside the box is dropped again at a new random
  /// point, up to this many times (as a person filling the box puts back what bounced out).
  int refills = 0;
};

/// True when `position_m` (an object's centre, base frame) lies inside the box's walls (their
/// mid-planes): on the box's floor, leaning on a wall from inside or on its rim.
bool inside_box(const BoxSpec& box, const Eigen::Vector3d& position_m);

/// One listed object: a primitive (`shape` + `size_m`) or a mesh object (`mesh` in `folder`).
struct ObjectEntry {
  std::string shape;
  std::vector<double> size_m;
  std::string mesh;
  std::string folder;
  double scale = 1.0;
  double density_kg_m3 = 700.0;
  double friction = 0.8;
  /// Explicit pose; with `rest_on_table` only x, y and the orientation are used.
  std::optional<Eigen::Isometry3d> pose;
  bool rest_on_table = false;
  /// An orientation without a position (`rpy_rad` alone): set down on the table at the
  /// centre of the scene's region, turned so.
  std::optional<Eigen::Matrix3d> orientation;
};

/// Objects drawn at random: procedural `shapes`, or meshes from `folder` (all or `names`).
struct RandomObjects {
  int count = 0;
  std::vector<std::string> shapes;
  std::string folder;
  std::vector<std::string> names;
  double min_scale = 1.0;
  double max_scale = 1.0;
  ProceduralRanges ranges;
};

/// A static box of the room around the table (a wall, a shelf board, a cabinet): seen by
/// the cameras and solid, never an object.
struct FixtureSpec {
  std::string name = "fixture";
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d size_m{0.1, 0.1, 0.1};
  double yaw_rad = 0.0;  ///< about the vertical
};

enum class Placement { kIsolated, kPile, kPacked };

struct SceneSpec {
  std::string file;  ///< where the scene was read from ("" if built in code)
  std::uint64_t seed = 0;
  TableSpec table;
  BoxSpec box;
  std::vector<FixtureSpec> fixtures;
  Placement placement = Placement::kPile;
  Eigen::AlignedBox2d region{Eigen::Vector2d(0.62, -0.25), Eigen::Vector2d(0.83, -0.02)};
  double drop_height_m = 0.2;
  std::vector<ObjectEntry> objects;
  RandomObjects random;
  std::vector<CameraSpec> cameras;
};

/// Reads a scene; throws antipode::Error located in the file for any bad or unknown key.
SceneSpec read_scene(const std::string& path);
/// Parses a scene from parameters (the mapping of a scene file).
SceneSpec parse_scene(const Parameters& params);
/// Parses one listed object (an item of a scene's `objects`); relative mesh folders are
/// resolved against `scene_file`.
ObjectEntry parse_object(const Parameters& params, const std::string& scene_file);
/// The default cameras: left and right of the table like the paper's two sensors, plus a
/// top and a front view.
std::vector<CameraSpec> default_cameras(const TableSpec& table);

}  // namespace antipode::cells
