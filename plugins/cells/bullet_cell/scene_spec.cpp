#include "scene_spec.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/core/yaml_limits.hpp"
#include "procedural_objects.hpp"

namespace fs = std::filesystem;

namespace antipode::cells {
namespace {

Eigen::VectorXd vector_at(const Parameters& p, const std::string& key, std::size_t n,
                          const Eigen::VectorXd& fallback) {
  if (!p.has(key)) {
    p.get<std::vector<double>>(key, {});
    return fallback;
  }
  const auto values = p.require<std::vector<double>>(key);
  if (values.size() != n) p.fail(key, "'" + key + "' needs " + std::to_string(n) + " numbers");
  // Checked here once for every vector: a NaN slips through the range checks after it (a
  // comparison with NaN is false, and Eigen's minCoeff/maxCoeff may skip it).
  for (const double v : values)
    if (!std::isfinite(v)) p.fail(key, "'" + key + "' must be finite numbers");
  return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(n));
}

double positive(const Parameters& p, const std::string& key, double fallback) {
  const double value = p.get<double>(key, fallback);
  if (!(value > 0.0)) p.fail(key, "'" + key + "' must be positive");
  return value;
}

// A 2-vector of sizes, each in (0, max_m].
Eigen::Vector2d sizes_at(const Parameters& p, const std::string& key,
                         const Eigen::Vector2d& fallback, double max_m) {
  Eigen::Vector2d value = vector_at(p, key, 2, fallback);
  if (!(value.minCoeff() > 0.0 && value.maxCoeff() <= max_m))
    p.fail(key, "'" + key + "' must be two sizes in (0, " + std::to_string(int(max_m)) + "] m");
  return value;
}

double friction_at(const Parameters& p, double fallback) {
  const double value = p.get<double>("friction", fallback);
  if (!(value > 0.0 && value <= 1.0)) p.fail("friction", "'friction' must be in (0, 1]");
  return value;
}

TableSpec parse_table(const Parameters& p) {
  TableSpec t;
  t.top_z_m = p.get<double>("top_z_m", t.top_z_m);
  if (!(std::abs(t.top_z_m) <= 10.0)) p.fail("top_z_m", "'top_z_m' must be in [-10, 10] m");
  t.center_m = vector_at(p, "center_m", 2, t.center_m);
  if (!(t.center_m.cwiseAbs().maxCoeff() <= 10.0))
    p.fail("center_m", "'center_m' must be within 10 m of the base");
  t.size_m = sizes_at(p, "size_m", t.size_m, 10.0);
  t.friction = friction_at(p, t.friction);
  p.reject_unknown();
  return t;
}

BoxSpec parse_box(const Parameters& p, const TableSpec& table) {
  BoxSpec b;
  b.present = true;
  b.center_m = vector_at(p, "center_m", 2, table.center_m);
  b.inner_size_m = sizes_at(p, "inner_size_m", b.inner_size_m, 10.0);
  b.wall_height_m = positive(p, "wall_height_m", b.wall_height_m);
  b.wall_thickness_m = positive(p, "wall_thickness_m", b.wall_thickness_m);
  b.removed_after_drop = p.get<bool>("removed_after_drop", false);
  b.refills = p.get<int>("refills", 0);
  if (b.refills < 0 || b.refills > 100) p.fail("refills", "'refills' must be in 0..100");
  p.reject_unknown();
  return b;
}

Eigen::Isometry3d pose_from(const Eigen::Vector3d& position, const Eigen::Vector3d& rpy) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = position;
  return pose;
}

void require_known_shape(const Parameters& p, const std::string& key, const std::string& shape) {
  const auto& known = procedural_shapes();
  if (std::find(known.begin(), known.end(), shape) == known.end())
    p.fail(key, unknown_shape_message(shape));
}

RandomObjects parse_random(const Parameters& p, const std::string& scene_file) {
  RandomObjects r;
  r.count = p.require<int>("count");
  if (r.count < 0 || r.count > 100) p.fail("count", "'count' must be in [0, 100]");
  r.shapes = p.get<std::vector<std::string>>("shapes", {});
  r.folder = p.get<std::string>("folder", "");
  r.names = p.get<std::vector<std::string>>("names", {});
  if (r.shapes.empty() == r.folder.empty())
    p.fail("shapes", "random objects need exactly one of 'shapes' and 'folder'");
  for (const auto& shape : r.shapes) require_known_shape(p, "shapes", shape);
  if (!r.folder.empty()) r.folder = resolve_path(r.folder, scene_file);
  const Eigen::Vector2d scale = vector_at(p, "scale", 2, Eigen::Vector2d(1.0, 1.0));
  if (!(scale[0] > 0.0 && scale[1] >= scale[0])) p.fail("scale", "'scale' needs 0 < lo <= hi");
  r.min_scale = scale[0];
  r.max_scale = scale[1];
  r.ranges.graspable_share = p.get<double>("graspable_share", r.ranges.graspable_share);
  p.reject_unknown();
  return r;
}

CameraSpec parse_camera(const std::string& name, const Parameters& p) {
  CameraSpec c;
  c.name = name;
  c.position_m = vector_at(p, "position_m", 3, c.position_m);
  c.look_at_m = vector_at(p, "look_at_m", 3, c.look_at_m);
  c.width_px = p.get<int>("width_px", c.width_px);
  c.height_px = p.get<int>("height_px", c.height_px);
  if (c.width_px < 1 || c.height_px < 1 || c.width_px > 4096 || c.height_px > 4096)
    p.fail("width_px", "camera image sizes must be in [1, 4096]");
  c.fx_px = positive(p, "fx_px", c.fx_px);
  c.fy_px = positive(p, "fy_px", c.fy_px);
  c.cx_px = p.get<double>("cx_px", (c.width_px - 1) / 2.0);
  c.cy_px = p.get<double>("cy_px", (c.height_px - 1) / 2.0);
  c.min_range_m = positive(p, "min_range_m", c.min_range_m);
  c.max_range_m = positive(p, "max_range_m", c.max_range_m);
  p.reject_unknown();
  return c;
}

Placement parse_placement(const Parameters& p) {
  const std::string text = p.get<std::string>("placement", "pile");
  if (text == "isolated") return Placement::kIsolated;
  if (text == "pile") return Placement::kPile;
  if (text == "packed") return Placement::kPacked;
  p.fail("placement", "'placement' must be isolated, pile or packed, got '" + text + "'");
}

}  // namespace

ObjectEntry parse_object(const Parameters& p, const std::string& scene_file) {
  ObjectEntry e;
  e.shape = p.get<std::string>("shape", "");
  e.size_m = p.get<std::vector<double>>("size_m", {});
  e.mesh = p.get<std::string>("mesh", "");
  e.folder = p.get<std::string>("folder", "");
  if (e.shape.empty() == e.mesh.empty())
    p.fail("shape", "an object needs exactly one of 'shape' and 'mesh'");
  if (!e.shape.empty()) require_known_shape(p, "shape", e.shape);
  if (!e.mesh.empty()) {
    if (e.folder.empty()) p.fail("folder", "a mesh object needs 'folder'");
    e.folder = resolve_path(e.folder, scene_file);
  }
  e.scale = positive(p, "scale", 1.0);
  e.density_kg_m3 = positive(p, "density_kg_m3", e.density_kg_m3);
  e.friction = friction_at(p, e.friction);
  const Eigen::Vector3d rpy = vector_at(p, "rpy_rad", 3, Eigen::Vector3d::Zero());
  if (p.has("position_m")) {
    const auto xyz = p.require<std::vector<double>>("position_m");
    if (xyz.size() != 2 && xyz.size() != 3)
      p.fail("position_m", "'position_m' needs [x, y] (resting on the table) or [x, y, z]");
    e.rest_on_table = xyz.size() == 2;
    e.pose = pose_from({xyz[0], xyz[1], xyz.size() == 3 ? xyz[2] : 0.0}, rpy);
  } else if (p.has("rpy_rad")) {
    e.orientation = pose_from(Eigen::Vector3d::Zero(), rpy).linear();
  }
  p.reject_unknown();
  return e;
}

std::vector<CameraSpec> default_cameras(const TableSpec& table) {
  const Eigen::Vector3d centre(table.center_m.x(), table.center_m.y(), table.top_z_m);
  auto camera = [&](const char* name, const Eigen::Vector3d& offset) {
    CameraSpec c;
    c.name = name;
    c.position_m = centre + offset;
    c.look_at_m = centre;
    return c;
  };
  return {camera("left", {-0.28, 0.58, 0.55}), camera("right", {-0.28, -0.58, 0.55}),
          camera("top", {0.0, 0.0, 0.75}), camera("front", {0.62, 0.0, 0.5})};
}

FixtureSpec parse_fixture(const Parameters& p) {
  FixtureSpec f;
  f.name = p.get<std::string>("name", f.name);
  f.center_m = vector_at(p, "center_m", 3, f.center_m);
  if (!(f.center_m.cwiseAbs().maxCoeff() <= 20.0))
    p.fail("center_m", "'center_m' must be within 20 m of the base");
  f.size_m = vector_at(p, "size_m", 3, f.size_m);
  if (!(f.size_m.minCoeff() > 0.0 && f.size_m.maxCoeff() <= 20.0))
    p.fail("size_m", "'size_m' must be three sizes in (0, 20] m");
  f.yaw_rad = p.get<double>("yaw_rad", 0.0);
  if (!(std::abs(f.yaw_rad) <= 10.0)) p.fail("yaw_rad", "'yaw_rad' must be in [-10, 10]");
  p.reject_unknown();
  return f;
}

// The entries of the list at `key` (at most 100, each named "<item> N of the scene"); none
// when the key is absent.
std::vector<Parameters> list_items(const Parameters& p, const std::string& key,
                                   const std::string& plural, const std::string& item) {
  std::vector<Parameters> items;
  if (!p.has(key)) return items;
  const YAML::Node list = p.yaml()[key];
  p.get<YAML::Node>(key, {});
  if (!list.IsSequence()) p.fail(key, "'" + key + "' must be a list");
  if (list.size() > 100)
    p.fail(key, "'" + key + "' lists " + std::to_string(list.size()) + " " + plural +
                    "; a scene holds at most 100");
  for (std::size_t i = 0; i < list.size(); ++i)
    items.emplace_back(list[i], item + " " + std::to_string(i + 1) + " of the scene", p.file());
  return items;
}

SceneSpec parse_scene(const Parameters& p) {
  SceneSpec s;
  s.file = p.file();
  s.seed = p.get<std::uint64_t>("seed", 0);
  s.table = parse_table(p.child("table"));
  if (p.has("box")) s.box = parse_box(p.child("box"), s.table);
  for (const Parameters& f : list_items(p, "fixtures", "boxes", "fixture"))
    s.fixtures.push_back(parse_fixture(f));
  s.placement = parse_placement(p);
  if (p.has("region")) {
    const Parameters r = p.child("region");
    s.region = Eigen::AlignedBox2d(vector_at(r, "min_m", 2, s.region.min()),
                                   vector_at(r, "max_m", 2, s.region.max()));
    r.reject_unknown();
  }
  s.drop_height_m = positive(p, "drop_height_m", s.drop_height_m);
  for (const Parameters& o : list_items(p, "objects", "objects", "object"))
    s.objects.push_back(parse_object(o, s.file));
  if (p.has("random_objects")) s.random = parse_random(p.child("random_objects"), s.file);
  if (s.objects.size() + std::size_t(s.random.count) > 100)
    p.fail("random_objects", "the scene holds " + std::to_string(s.objects.size()) +
                                 " listed and " + std::to_string(s.random.count) +
                                 " random objects; at most 100 in all");
  if (p.has("cameras")) {
    const Parameters cams = p.child("cameras");
    if (!cams.yaml().IsMap()) p.fail("cameras", "'cameras' must map camera names to cameras");
    for (const auto& item : cams.yaml()) {
      if (!item.first.IsScalar()) p.fail("cameras", "'cameras' must map camera names to cameras");
      s.cameras.push_back(parse_camera(item.first.Scalar(), cams.child(item.first.Scalar())));
    }
  } else {
    s.cameras = default_cameras(s.table);
  }
  if (s.placement == Placement::kIsolated && s.objects.size() + s.random.count != 1)
    p.fail("placement", "an isolated scene holds exactly one object");
  p.reject_unknown();
  return s;
}

SceneSpec read_scene(const std::string& path) {
  require_regular_file(path, "a scene file");
  if (!std::filesystem::exists(path)) throw Error("scene '" + path + "': no such file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw Error("scene '" + path + "': " + e.what());
  }
  check_yaml_size(root, "scene '" + path + "'");
  if (!root.IsMap())
    throw Error("scene '" + path + "': " +
                (root.IsNull() ? std::string("the file is empty") : "not a map of scene keys") +
                " (see docs/cell.md, \"Scene files\")");
  return parse_scene(Parameters(root, "scene '" + path + "'", path));
}

bool inside_box(const BoxSpec& box, const Eigen::Vector3d& position_m) {
  const Eigen::Vector2d half =
      box.inner_size_m / 2 + Eigen::Vector2d::Constant(box.wall_thickness_m / 2);
  return ((position_m.head<2>() - box.center_m).array().abs() <= half.array()).all();
}

}  // namespace antipode::cells
