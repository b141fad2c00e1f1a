#include "scene_builder.hpp"

#include <cmath>

#include "antipode/core/error.hpp"
#include "mesh_objects.hpp"

namespace antipode::cells {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Isometry3d translation(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

// Adds the table, the room's fixtures and the box; returns the box walls' ids.
std::vector<int> add_table_and_box(const SceneSpec& spec, PhysicsWorld& world) {
  const TableSpec& t = spec.table;
  world.add_fixture_box("table", translation(t.center_m.x(), t.center_m.y(), t.top_z_m - 0.025),
                        {t.size_m.x() / 2, t.size_m.y() / 2, 0.025}, t.friction);
  for (const FixtureSpec& f : spec.fixtures) {
    Eigen::Isometry3d pose = translation(f.center_m.x(), f.center_m.y(), f.center_m.z());
    pose.rotate(Eigen::AngleAxisd(f.yaw_rad, Eigen::Vector3d::UnitZ()));
    world.add_fixture_box(f.name, pose, f.size_m / 2, t.friction);
  }
  std::vector<int> walls;
  if (!spec.box.present) return walls;
  const BoxSpec& b = spec.box;
  const double hx = b.inner_size_m.x() / 2, hy = b.inner_size_m.y() / 2;
  const double th = b.wall_thickness_m / 2, hz = b.wall_height_m / 2;
  const double z = t.top_z_m + hz;
  for (int side : {-1, 1}) {
    walls.push_back(world.add_fixture_box(
        "box wall", translation(b.center_m.x() + side * (hx + th), b.center_m.y(), z),
        {th, hy + 2 * th, hz}, t.friction));
    walls.push_back(world.add_fixture_box(
        "box wall", translation(b.center_m.x(), b.center_m.y() + side * (hy + th), z), {hx, th, hz},
        t.friction));
  }
  return walls;
}

Eigen::Matrix3d random_rotation(RandomStream& random) {
  Eigen::Quaterniond q(random.normal(), random.normal(), random.normal(), random.normal());
  return q.normalized().toRotationMatrix();
}

Eigen::Matrix3d yaw(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Half the vertical extent of `model` rotated by `rotation`.
double half_height(const ObjectModel& model, const Eigen::Matrix3d& rotation) {
  double lo = 1e9, hi = -1e9;
  for (const auto& v : model.visual->vertices) {
    const double z = (rotation * v.cast<double>()).z();
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  return std::max(-lo, hi);
}

double footprint_radius(const ObjectModel& model) {
  double r = 0.0;
  for (const auto& v : model.visual->vertices) r = std::max(r, double(v.head<2>().norm()));
  return r;
}

ObjectModel entry_model(const ObjectEntry& e) {
  if (e.shape.empty())
    return load_mesh_object(e.folder, e.mesh, e.scale, e.density_kg_m3, e.friction);
  std::vector<double> size = e.size_m;
  for (double& s : size) s *= e.scale;
  return make_object(e.shape, size, e.density_kg_m3, e.friction);
}

ObjectModel random_model(const RandomObjects& r, RandomStream& random, MeshCache& meshes) {
  if (!r.shapes.empty()) {
    const std::string& shape = r.shapes[random.below(r.shapes.size())];
    return make_random_object(shape, r.ranges, random);
  }
  const auto& names = r.names.empty() ? meshes.names(r.folder) : r.names;
  const std::string& name = names[random.below(names.size())];
  const double scale = random.uniform(r.min_scale, r.max_scale);
  const double density = random.uniform(r.ranges.min_density_kg_m3, r.ranges.max_density_kg_m3);
  const double friction = random.uniform(r.ranges.min_friction, r.ranges.max_friction);
  return load_mesh_object(r.folder, name, scale, density, friction);
}

// Where a model without an explicit pose goes, by the scene's placement rule.
Eigen::Isometry3d placed_pose(const SceneSpec& spec, const ObjectModel& model, RandomStream& random,
                              const std::vector<Eigen::Vector3d>& taken) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const double top = spec.table.top_z_m;
  if (spec.placement == Placement::kPile) {
    const double margin = std::min(footprint_radius(model), 0.4 * spec.box.inner_size_m.minCoeff());
    const Eigen::Vector2d half = spec.box.present ? Eigen::Vector2d(spec.box.inner_size_m / 2)
                                                  : Eigen::Vector2d(spec.region.sizes() / 2);
    const Eigen::Vector2d centre = spec.box.present ? spec.box.center_m : spec.region.center();
    pose.linear() = random_rotation(random);
    pose.translation() << centre.x() + random.uniform(-1, 1) * (half.x() - margin),
        centre.y() + random.uniform(-1, 1) * (half.y() - margin),
        top + spec.drop_height_m + half_height(model, pose.linear());
    return pose;
  }
  const double radius = footprint_radius(model);
  Eigen::Vector2d xy = spec.region.center();
  for (int attempt = 0; attempt < 100; ++attempt) {
    xy = spec.region.min() +
         Eigen::Vector2d(random.uniform(), random.uniform()).cwiseProduct(spec.region.sizes());
    bool free = true;
    for (const auto& other : taken)
      if ((other.head<2>() - xy).norm() < other.z() + radius + 0.005) free = false;
    if (free) break;
  }
  pose.linear() = spec.placement == Placement::kIsolated
                      ? Eigen::Matrix3d(yaw(random.uniform(0, 2 * kPi)) *
                                        (random.uniform() < 0.5 ? Eigen::Matrix3d::Identity()
                                                                : random_rotation(random)))
                      : yaw(random.uniform(0, 2 * kPi));
  pose.translation() << xy.x(), xy.y(), top + half_height(model, pose.linear()) + 0.002;
  return pose;
}

// Up to the box's `refills` rounds: each object of a pile that came to rest outside the box
// (bounced out, or knocked out by a later one) is dropped again at a new random point.
void refill_box(const SceneSpec& spec, const std::vector<ObjectModel>& models, RandomStream& random,
                PhysicsWorld& world, std::vector<int>& ids) {
  if (spec.placement != Placement::kPile || !spec.box.present) return;
  for (int round = 0; round < spec.box.refills; ++round) {
    bool refilled = false;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (inside_box(spec.box, world.pose(ids[i]).translation())) continue;
      world.remove_body(ids[i]);
      ids[i] = world.add_object(models[i], placed_pose(spec, models[i], random, {}));
      world.settle(1.5);
      refilled = true;
    }
    if (!refilled) return;
    world.settle(2.0);
  }
}

void remove_fallen(const SceneSpec& spec, PhysicsWorld& world, std::vector<int>& ids) {
  std::vector<int> kept;
  for (int id : ids) {
    if (world.pose(id).translation().z() < spec.table.top_z_m - 0.01)
      world.remove_body(id);
    else
      kept.push_back(id);
  }
  ids = kept;
}

}  // namespace

const std::vector<std::string>& MeshCache::names(const std::string& folder) {
  auto it = listings_.find(folder);
  if (it == listings_.end()) it = listings_.emplace(folder, list_mesh_objects(folder)).first;
  return it->second;
}

std::vector<ObjectModel> scene_objects(const SceneSpec& spec, std::uint64_t seed,
                                       MeshCache& meshes) {
  std::vector<ObjectModel> models;
  for (const auto& entry : spec.objects) models.push_back(entry_model(entry));
  RandomStream random = RandomStream(seed).derive(1);
  for (int i = 0; i < spec.random.count; ++i) {
    RandomStream item = random.derive(std::uint64_t(i));
    models.push_back(random_model(spec.random, item, meshes));
  }
  return models;
}

std::vector<int> build_scene(const SceneSpec& spec, std::uint64_t seed, MeshCache& meshes,
                             PhysicsWorld& world) {
  const std::vector<int> walls = add_table_and_box(spec, world);
  const std::vector<ObjectModel> models = scene_objects(spec, seed, meshes);
  RandomStream random = RandomStream(seed).derive(2);
  std::vector<int> ids;
  std::vector<Eigen::Vector3d> taken;  // x, y, footprint radius
  for (std::size_t i = 0; i < models.size(); ++i) {
    const ObjectEntry* entry = i < spec.objects.size() ? &spec.objects[i] : nullptr;
    Eigen::Isometry3d pose;
    if (entry && entry->pose) {
      pose = *entry->pose;
      if (entry->rest_on_table)
        pose.translation().z() = spec.table.top_z_m + half_height(models[i], pose.linear()) + 0.001;
    } else if (entry && entry->orientation) {
      pose = Eigen::Isometry3d::Identity();
      pose.linear() = *entry->orientation;
      pose.translation() << spec.region.center(),
          spec.table.top_z_m + half_height(models[i], pose.linear()) + 0.001;
    } else {
      pose = placed_pose(spec, models[i], random, taken);
    }
    taken.emplace_back(pose.translation().x(), pose.translation().y(), footprint_radius(models[i]));
    ids.push_back(world.add_object(models[i], pose));
    if (spec.placement == Placement::kPile) world.settle(1.5);
  }
  world.settle(2.0);
  refill_box(spec, models, random, world, ids);
  if (spec.box.removed_after_drop) {
    for (int wall : walls) world.remove_body(wall);
    world.settle(2.0);
  }
  remove_fallen(spec, world, ids);
  return ids;
}

}  // namespace antipode::cells
