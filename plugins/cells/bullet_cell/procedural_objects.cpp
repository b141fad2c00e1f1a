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

// An object made of convex parts: the frame is moved to the centre of mass.
ObjectModel finish_parts(std::string name, TriangleMesh visual, std::vector<TriangleMesh> hulls,
                         double density, double friction, double width) {
  centre_on_mass(visual, hulls);
  CollisionSpec c;
  c.kind = CollisionKind::kHulls;
  c.hulls = std::move(hulls);
  return finish(std::move(name), std::move(visual), std::move(c), density, friction, width);
}

constexpr float kPi = 3.14159265358979f;

// The mesh of several closed parts that touch or barely overlap (their volumes add up).
TriangleMesh union_of(const std::vector<TriangleMesh>& parts) {
  TriangleMesh mesh;
  for (const auto& part : parts) mesh.append(part);
  return mesh;
}

TriangleMesh moved(TriangleMesh mesh, const Eigen::Vector3f& offset) {
  mesh.transform(Eigen::Affine3f(Eigen::Translation3f(offset)));
  return mesh;
}

// A box spanning [lo, hi].
TriangleMesh box_between(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  return moved(box_mesh((hi - lo) / 2.f), (lo + hi) / 2.f);
}

// Bottle {body diameter, total height, neck diameter, neck length}: a cylindrical body, a
// 45-degree conical shoulder and a cylindrical neck. Collision: body with shoulder, and neck.
ObjectModel make_bottle(const std::vector<double>& s, double density, double friction) {
  const float radius = float(s[0] / 2), height = float(s[1]), neck_radius = float(s[2] / 2),
              neck = float(s[3]);
  if (!(neck_radius < radius)) throw Error("bottle neck must be narrower than its body");
  const float top = height / 2, bottom = -height / 2, neck_start = top - neck,
              shoulder = neck_start - (radius - neck_radius);
  if (!(shoulder > bottom + 0.005f))
    throw Error("bottle too short for its neck and shoulder (body under 5 mm)");
  TriangleMesh visual = revolution_mesh({{0.f, bottom},
                                         {radius, bottom},
                                         {radius, shoulder},
                                         {neck_radius, neck_start},
                                         {neck_radius, top},
                                         {0.f, top}},
                                        32);
  std::vector<TriangleMesh> hulls = {
      revolution_mesh({{0.f, bottom},
                       {radius, bottom},
                       {radius, shoulder},
                       {neck_radius, neck_start},
                       {0.f, neck_start}},
                      32),
      moved(cylinder_mesh(neck_radius, neck), Eigen::Vector3f(0.f, 0.f, neck_start + neck / 2))};
  return finish_parts("bottle", std::move(visual), std::move(hulls), density, friction, s[0]);
}

// Rings of a tube of `radius` along a circular arc in the plane spanned by `in_plane_x` and
// `in_plane_y` (centre of the circle `centre`, radius `bend`, from angle a0 to a1), with a
// straight run of `lead` before and after; hemispherical ends when `round_ends`, else flat.
std::vector<SweepRing> arc_tube(const Eigen::Vector3f& centre, const Eigen::Vector3f& in_plane_x,
                                const Eigen::Vector3f& in_plane_y, float bend, float a0, float a1,
                                float radius, float lead, bool round_ends, int steps) {
  const Eigen::Vector3f normal = in_plane_x.cross(in_plane_y);
  const float sign = a1 > a0 ? 1.f : -1.f;
  auto point = [&](float a) {
    return Eigen::Vector3f(centre + bend * (std::cos(a) * in_plane_x + std::sin(a) * in_plane_y));
  };
  auto tangent = [&](float a) {
    return Eigen::Vector3f(sign * (-std::sin(a) * in_plane_x + std::cos(a) * in_plane_y));
  };
  // A ring at `c` facing along `t`, with u x v = t.
  auto ring = [&](const Eigen::Vector3f& c, const Eigen::Vector3f& t, float r) {
    const Eigen::Vector3f u = normal, v = t.cross(u);
    return SweepRing{c, u, v, r};
  };
  std::vector<SweepRing> rings;
  const int cap_steps = 6;
  const Eigen::Vector3f start = point(a0) - lead * tangent(a0),
                        end = point(a1) + lead * tangent(a1);
  if (round_ends) {
    for (int i = 0; i < cap_steps; ++i) {
      const float b = 0.5f * kPi * float(i) / float(cap_steps);
      rings.push_back(ring(start - radius * std::cos(b) * tangent(a0), tangent(a0),
                           i == 0 ? 0.f : radius * std::sin(b)));
    }
  } else {
    rings.push_back(ring(start, tangent(a0), 0.f));
  }
  if (lead > 0.f) rings.push_back(ring(start, tangent(a0), radius));
  for (int i = 0; i <= steps; ++i) {
    const float a = a0 + (a1 - a0) * float(i) / float(steps);
    rings.push_back(ring(point(a), tangent(a), radius));
  }
  if (lead > 0.f) rings.push_back(ring(end, tangent(a1), radius));
  if (round_ends) {
    for (int i = cap_steps - 1; i >= 0; --i) {
      const float b = 0.5f * kPi * float(i) / float(cap_steps);
      rings.push_back(ring(end + radius * std::cos(b) * tangent(a1), tangent(a1),
                           i == 0 ? 0.f : radius * std::sin(b)));
    }
  } else {
    rings.push_back(ring(end, tangent(a1), 0.f));
  }
  return rings;
}

// One convex hull per pair of neighbouring rings of a tube (the end caps join the first and
// last pair).
std::vector<TriangleMesh> tube_hulls(const std::vector<SweepRing>& rings, int segments) {
  std::vector<std::size_t> full;
  for (std::size_t i = 0; i < rings.size(); ++i)
    if (rings[i].radius_m > 0.f) full.push_back(i);
  std::vector<TriangleMesh> hulls;
  for (std::size_t k = 0; k + 1 < full.size(); ++k) {
    const std::size_t first = k == 0 ? 0 : full[k];
    const std::size_t last = k + 2 == full.size() ? rings.size() - 1 : full[k + 1];
    hulls.push_back(sweep_piece(rings, first, last, segments));
  }
  return hulls;
}

// Mug {diameter, height}: a solid cylindrical body and a semicircular handle of round section
// on its +x side, in the xz plane.
ObjectModel make_mug(const std::vector<double>& s, double density, double friction) {
  const float radius = float(s[0] / 2), height = float(s[1]);
  const float tube = std::clamp(0.1f * float(s[0]), 0.003f, 0.006f);
  const float reach = std::min(0.35f * height, height / 2 - tube - 0.003f);
  if (!(reach > 2 * tube)) throw Error("mug too low for its handle");
  // The handle's ends run into the body far enough to close the gap the curved wall leaves.
  const float lead = tube * tube / radius + 0.001f;
  const std::vector<SweepRing> handle =
      arc_tube(Eigen::Vector3f(radius, 0.f, 0.f), Eigen::Vector3f::UnitX(),
               Eigen::Vector3f::UnitZ(), reach, -0.5f * kPi, 0.5f * kPi, tube, lead, false, 12);
  TriangleMesh body = cylinder_mesh(radius, height);
  std::vector<TriangleMesh> hulls = tube_hulls(handle, 12);
  hulls.insert(hulls.begin(), body);
  return finish_parts("mug", union_of({body, sweep_mesh(handle, 12)}), std::move(hulls), density,
                      friction, s[0]);
}

// Banana {diameter, length along the curve, bend radius}: a capsule bent along a circular arc
// lying in the xy plane.
ObjectModel make_banana(const std::vector<double>& s, double density, double friction) {
  const float radius = float(s[0] / 2), length = float(s[1]), bend = float(s[2]);
  if (!(length > s[0])) throw Error("banana length must exceed its diameter");
  if (!(bend > 1.5f * radius)) throw Error("banana bend radius must exceed 1.5 x its radius");
  const float angle = (length - 2 * radius) / bend;
  if (angle > 1.5f * kPi) throw Error("banana too long for its bend radius (over 270 degrees)");
  const std::vector<SweepRing> rings =
      arc_tube(Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitX(), Eigen::Vector3f::UnitY(), bend,
               0.5f * kPi - angle / 2, 0.5f * kPi + angle / 2, radius, 0.f, true,
               std::max(2, int(std::ceil(angle / 0.2f))));
  return finish_parts("banana", sweep_mesh(rings, 16), tube_hulls(rings, 16), density, friction,
                      s[0]);
}

// L {bar width, long leg, short leg, height}: two bars of the same width in the xy plane,
// extruded along z. T {bar width, cross bar length, stem length, height}.
ObjectModel make_bars(const std::string& shape, const std::vector<double>& s, double density,
                      double friction) {
  const float w = float(s[0]), a = float(s[1]), b = float(s[2]), h = float(s[3]) / 2;
  std::vector<TriangleMesh> parts;
  if (shape == "l_shape") {
    if (!(a > w && b > w)) throw Error("l_shape legs must be longer than the bar width");
    parts = {box_between({0.f, 0.f, -h}, {w, a, h}), box_between({w, 0.f, -h}, {b, w, h})};
  } else {
    if (!(a > w)) throw Error("t_shape cross bar must be longer than the bar width");
    parts = {box_between({-w / 2, 0.f, -h}, {w / 2, b, h}),
             box_between({-a / 2, b, -h}, {a / 2, b + w, h})};
  }
  return finish_parts(shape, union_of(parts), parts, density, friction, s[0]);
}

// The graspable width: inside the gripper's range for `graspable_share` of the objects.
double draw_width(const ProceduralRanges& r, RandomStream& random) {
  if (random.uniform() < r.graspable_share)
    return random.uniform(r.min_graspable_m, r.max_graspable_m);
  if (random.uniform() < 0.25) return random.uniform(0.015, r.min_graspable_m - 0.003);
  return random.uniform(r.max_graspable_m + 0.005, r.max_graspable_m + 0.04);
}

}  // namespace

std::string unknown_shape_message(const std::string& shape) {
  std::string known;
  for (const auto& name : procedural_shapes()) known += (known.empty() ? "" : ", ") + name;
  return "unknown object shape '" + shape + "'" + did_you_mean(shape, procedural_shapes()) +
         " (known: " + known + ")";
}

const std::vector<std::string>& procedural_shapes() {
  static const std::vector<std::string> shapes = {"box",       "cylinder", "sphere", "capsule",
                                                  "ellipsoid", "bottle",   "mug",    "banana",
                                                  "l_shape",   "t_shape"};
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
  if (shape == "bottle") {
    require_sizes(shape, s, 4);
    return make_bottle(s, density, friction);
  }
  if (shape == "mug") {
    require_sizes(shape, s, 2);
    return make_mug(s, density, friction);
  }
  if (shape == "banana") {
    require_sizes(shape, s, 3);
    return make_banana(s, density, friction);
  }
  if (shape == "l_shape" || shape == "t_shape") {
    require_sizes(shape, s, 4);
    return make_bars(shape, s, density, friction);
  }
  throw Error(unknown_shape_message(shape));
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
  else if (shape == "bottle") {
    const double neck_d = std::max(0.012, width * random.uniform(0.35, 0.5));
    const double neck = random.uniform(0.02, 0.05);
    size = {width, neck + (width - neck_d) / 2 + random.uniform(0.05, 0.15), neck_d, neck};
  } else if (shape == "mug")
    size = {width, random.uniform(0.06, 0.11)};
  else if (shape == "banana") {
    const double length = width + random.uniform(0.08, 0.17);
    size = {width, length, std::max({random.uniform(0.08, 0.2), (length - width) / 2.5, width})};
  } else if (shape == "l_shape")
    size = {width, width + random.uniform(0.04, 0.1), width + random.uniform(0.03, 0.08),
            random.uniform(0.025, 0.08)};
  else if (shape == "t_shape")
    size = {width, width + random.uniform(0.05, 0.1), random.uniform(0.04, 0.1),
            random.uniform(0.025, 0.08)};
  return make_object(shape, size, density, friction);
}

}  // namespace antipode::cells
