#include "procedural_objects.hpp"

#include <algorithm>
#include <cmath>

#include "antipode/core/error.hpp"
#include "primitive_meshes.hpp"

namespace antipode::cells {
namespace {

void require_sizes(const std::string& shape, const std::vector<double>& size_m, std::size_t n) {
  if (size_m.size() != n) throw Error(shape + " needs " + std::to_string(n) + " size value(s)");
  for (double s : size_m)
    if (!(s > 0.0 && s < 2.0)) throw Error(shape + " sizes must be in (0, 2) m");
}

ObjectModel finish(std::string name, TriangleMesh visual, CollisionSpec collision, double density,
                   double friction, double width) {
  ObjectModel model;
  model.name = std::move(name);
  model.mass_kg = std::max(0.005, visual.volume() * density);
  model.visual = std::make_shared<const TriangleMesh>(std::move(visual));
  model.collision = std::move(collision);
  model.friction = friction;
  model.graspable_width_m = width;
  return model;
}

// The graspable width: inside the gripper's range for `graspable_share` of the objects.
double draw_width(const ProceduralRanges& r, RandomStream& random) {
  if (random.uniform() < r.graspable_share)
    return random.uniform(r.min_graspable_m, r.max_graspable_m);
  if (random.uniform() < 0.25) return random.uniform(0.015, r.min_graspable_m - 0.003);
  return random.uniform(r.max_graspable_m + 0.005, r.max_graspable_m + 0.04);
}

}  // namespace

const std::vector<std::string>& procedural_shapes() {
  static const std::vector<std::string> shapes = {"box", "cylinder", "sphere", "capsule",
                                                  "ellipsoid"};
  return shapes;
}

ObjectModel make_object(const std::string& shape, const std::vector<double>& s, double density,
                        double friction) {
  CollisionSpec c;
  if (shape == "box") {
    require_sizes(shape, s, 3);
    c.kind = CollisionKind::kBox;
    c.half_extents_m = Eigen::Vector3d(s[0], s[1], s[2]) / 2.0;
    return finish(shape, box_mesh(c.half_extents_m.cast<float>()), c, density, friction,
                  std::min(s[0], s[1]));
  }
  if (shape == "cylinder") {
    require_sizes(shape, s, 2);
    TriangleMesh mesh = cylinder_mesh(float(s[0] / 2.0), float(s[1]));
    c.kind = CollisionKind::kHulls;
    c.hulls = {mesh};
    return finish(shape, std::move(mesh), c, density, friction, s[0]);
  }
  if (shape == "sphere") {
    require_sizes(shape, s, 1);
    c.kind = CollisionKind::kSphere;
    c.radius_m = s[0] / 2.0;
    return finish(shape, ellipsoid_mesh(Eigen::Vector3f::Constant(float(c.radius_m))), c, density,
                  friction, s[0]);
  }
  if (shape == "capsule") {
    require_sizes(shape, s, 2);
    if (s[1] < s[0]) throw Error("capsule length must be at least its diameter");
    c.kind = CollisionKind::kCapsule;
    c.radius_m = s[0] / 2.0;
    c.half_height_m = (s[1] - s[0]) / 2.0;
    return finish(shape, capsule_mesh(float(c.radius_m), float(s[1] - s[0])), c, density, friction,
                  s[0]);
  }
  if (shape == "ellipsoid") {
    require_sizes(shape, s, 3);
    TriangleMesh mesh = ellipsoid_mesh(Eigen::Vector3f(s[0], s[1], s[2]).cast<float>() / 2.f, 16);
    c.kind = CollisionKind::kHulls;
    c.hulls = {mesh};
    return finish(shape, std::move(mesh), c, density, friction, std::min(s[0], s[1]));
  }
  throw Error("unknown object shape '" + shape +
              "' (known: box, cylinder, sphere, capsule, ellipsoid)");
}

ObjectModel make_random_object(const std::string& shape, const ProceduralRanges& r,
                               RandomStream& random) {
  const double width = draw_width(r, random);
  const double density = random.uniform(r.min_density_kg_m3, r.max_density_kg_m3);
  const double friction = random.uniform(r.min_friction, r.max_friction);
  std::vector<double> size;
  if (shape == "box")
    size = {width, random.uniform(width, width + 0.06), random.uniform(0.03, 0.15)};
  else if (shape == "cylinder")
    size = {width, random.uniform(0.04, 0.15)};
  else if (shape == "sphere")
    size = {std::min(width, 0.08)};
  else if (shape == "capsule")
    size = {width, width + random.uniform(0.02, 0.1)};
  else if (shape == "ellipsoid")
    size = {width, random.uniform(width, width + 0.04), random.uniform(0.03, 0.12)};
  return make_object(shape, size, density, friction);
}

}  // namespace antipode::cells
