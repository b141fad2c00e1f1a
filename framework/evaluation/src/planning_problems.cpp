#include "antipode/evaluation/planning_problems.hpp"

#include <cmath>
#include <string>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/core/random.hpp"
#include "antipode/core/yaml_limits.hpp"

namespace antipode::evaluation {
namespace {

Eigen::Vector3d vector3(const Parameters& p, const char* key, const Eigen::Vector3d& fallback) {
  if (!p.has(key)) {
    (void)p.get<std::vector<double>>(key, {});  // asked
    return fallback;
  }
  const auto v = p.get<std::vector<double>>(key, {});
  if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    p.fail(key, std::string(key) + " needs three finite numbers");
  return {v[0], v[1], v[2]};
}

// The object of `p`: its shape, size and nominal pose.
Obstacle solid_of(const Parameters& p) {
  Obstacle o;
  o.name = p.require<std::string>("name");
  if (p.has("box_m") == p.has("cylinder"))
    p.fail("name", "object '" + o.name +
                       "' needs one shape: box_m [x, y, z] or cylinder "
                       "{ radius_m, length_m }");
  (void)p.child("cylinder");  // asked, whichever shape it is
  if (p.has("box_m")) {
    o.size_m = vector3(p, "box_m", Eigen::Vector3d::Zero());
    if (!(o.size_m.array() > 0.0).all()) p.fail("box_m", "box_m: sizes must be positive");
  } else {
    (void)p.get<std::vector<double>>("box_m", {});
    o.shape = Obstacle::Shape::kCylinder;
    const Parameters c = p.child("cylinder");
    o.size_m = {c.require<double>("radius_m"), c.require<double>("length_m"), 0.0};
    if (!(o.size_m.x() > 0.0 && o.size_m.y() > 0.0))
      c.fail("radius_m", "a cylinder's radius_m and length_m must be positive");
    c.reject_unknown();
  }
  o.X_BaseObstacle.translation() = vector3(p, "position_m", Eigen::Vector3d::Zero());
  (void)p.get<std::vector<double>>("quaternion_xyzw", {});
  if (p.has("quaternion_xyzw")) {
    const auto q = p.get<std::vector<double>>("quaternion_xyzw", {});
    Eigen::Quaterniond quaternion(q.size() == 4 ? q[3] : 0, q.size() == 4 ? q[0] : 0,
                                  q.size() == 4 ? q[1] : 0, q.size() == 4 ? q[2] : 0);
    if (q.size() != 4 || !(quaternion.norm() > 1e-9))
      p.fail("quaternion_xyzw", "quaternion_xyzw needs four numbers, not all zero");
    o.X_BaseObstacle.linear() = quaternion.normalized().toRotationMatrix();
  }
  p.reject_unknown();
  return o;
}

void read_variation(const Parameters& p, Eigen::Vector3d& sigma_m, Eigen::Vector3d& bound_rad) {
  sigma_m = vector3(p, "position_m", Eigen::Vector3d::Zero());
  bound_rad = vector3(p, "rotation_rad", Eigen::Vector3d::Zero());
  if ((sigma_m.array() < 0.0).any() || (bound_rad.array() < 0.0).any())
    p.fail("position_m", "variations must not be negative");
  p.reject_unknown();
}

// A rigid motion drawn as the scene's sampler draws it.
Eigen::Isometry3d draw(RandomStream& random, const Eigen::Vector3d& sigma_m,
                       const Eigen::Vector3d& bound_rad) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int a = 0; a < 3; ++a) T.translation()(a) = sigma_m(a) * random.normal();
  for (int a = 0; a < 3; ++a)
    T.rotate(
        Eigen::AngleAxisd(random.uniform(-bound_rad(a), bound_rad(a)), Eigen::Vector3d::Unit(a)));
  return T;
}

}  // namespace

PlanningScene read_planning_scene(const std::string& path) {
  const std::string what = "planning scene '" + path + "'";
  const YAML::Node root = load_yaml_map(path, what, "scene keys", "scenes/planning/");
  const Parameters p(root, what, path);
  PlanningScene scene;
  scene.path = path;
  const YAML::Node objects = p.get<YAML::Node>("objects", YAML::Node());
  if (!objects.IsSequence() || objects.size() == 0)
    p.fail("objects", "objects: a list of { name, box_m | cylinder, position_m }");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Parameters object(objects[i], what + " object " + std::to_string(i + 1), path);
    SceneSolid solid;  // no variation unless stated
    solid.solid = solid_of(object);
    scene.objects.push_back(solid);
  }
  const Parameters variation = p.child("variation");
  if (variation.has("world"))
    read_variation(variation.child("world"), scene.world_sigma_m, scene.world_bound_rad);
  const Parameters moves = variation.child("objects");
  for (const auto& entry : moves.yaml()) {
    const std::string name = entry.first.as<std::string>();
    SceneSolid* object = nullptr;
    for (SceneSolid& o : scene.objects)
      if (o.solid.name == name) object = &o;
    if (object == nullptr) moves.fail(name, "variation: no object '" + name + "'");
    read_variation(moves.child(name), object->position_sigma_m, object->rotation_bound_rad);
  }
  variation.reject_unknown();
  scene.targets = p.require<std::vector<std::string>>("targets");
  for (const std::string& t : scene.targets) {
    bool found = false;
    for (const SceneSolid& o : scene.objects) found = found || o.solid.name == t;
    if (!found) p.fail("targets", "targets: no object '" + t + "'");
  }
  if (scene.targets.empty()) p.fail("targets", "targets: name at least one object");
  const std::string approach = p.get<std::string>("approach", "front");
  if (approach != "front" && approach != "down")
    p.fail("approach", "approach must be front or down, got '" + approach + "'");
  scene.approach_down = approach == "down";
  scene.standoff_m = p.get<double>("standoff_m", scene.standoff_m);
  if (!(scene.standoff_m >= 0.0 && scene.standoff_m < 1.0))
    p.fail("standoff_m", "standoff_m must be in [0, 1) m");
  if (!p.has("robots")) p.fail("robots", "missing required parameter 'robots'");
  const Parameters robots = p.child("robots");
  for (const auto& entry : robots.yaml()) {
    const std::string name = entry.first.as<std::string>();
    const Parameters r = robots.child(name);
    PlanningScene::Placement placement;
    placement.robot = name;
    placement.frame = r.require<std::string>("frame");
    placement.offset_m = vector3(r, "offset_m", Eigen::Vector3d::Zero());
    placement.standoff_m = r.number_in("standoff_m", scene.standoff_m, 0.0, 1.0);
    scene.robots.push_back(placement);
    r.reject_unknown();
  }
  p.reject_unknown();
  return scene;
}

namespace {

const PlanningScene::Placement& placement_of(const PlanningScene& scene, const std::string& robot) {
  for (const PlanningScene::Placement& p : scene.robots)
    if (p.robot == robot) return p;
  std::string placed;
  for (const PlanningScene::Placement& p : scene.robots)
    placed += (placed.empty() ? "" : ", ") + p.robot;
  throw Error(scene.path + ": places no robot '" + robot + "' (it places " + placed + ")", {},
              "add it under `robots:` with the frame and offset the scene stands at");
}

}  // namespace

const std::string& planning_frame(const PlanningScene& scene, const std::string& robot) {
  return placement_of(scene, robot).frame;
}

PlanningQuery sample_planning_query(const PlanningScene& scene, const std::string& robot,
                                    const Eigen::Isometry3d& X_BaseFrame, std::uint64_t seed) {
  const PlanningScene::Placement& placement = placement_of(scene, robot);
  RandomStream random(seed);
  // The world's motion about the frame's origin, after the offset (MotionBenchMaker's order).
  const Eigen::Isometry3d world = draw(random, scene.world_sigma_m, scene.world_bound_rad);
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  offset.translation() = placement.offset_m;
  const Eigen::Isometry3d X_BaseScene = X_BaseFrame * world * offset;
  PlanningQuery query;
  query.target = scene.targets[seed % scene.targets.size()];
  for (const SceneSolid& object : scene.objects) {
    Obstacle o = object.solid;
    o.X_BaseObstacle = X_BaseScene * object.solid.X_BaseObstacle *
                       draw(random, object.position_sigma_m, object.rotation_bound_rad);
    if (o.name == query.target) {
      // The hand's x (its approach) along the target's x, or down its z; y (closing) along
      // the target's y.
      Eigen::Matrix3d R_ObjectHand = Eigen::Matrix3d::Identity();
      if (scene.approach_down) R_ObjectHand << 0, 0, 1, 0, 1, 0, -1, 0, 0;
      query.X_BaseHand.linear() = o.X_BaseObstacle.linear() * R_ObjectHand;
      query.X_BaseHand.translation() =
          o.X_BaseObstacle.translation() - placement.standoff_m * query.X_BaseHand.linear().col(0);
    }
    query.obstacles.push_back(std::move(o));
  }
  return query;
}

}  // namespace antipode::evaluation
