#include "bullet_cell.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/geometry/narrowest_extent.hpp"
#include "antipode/robot/robot_file.hpp"

namespace antipode::cells {
namespace {

// What BulletCell::save() keeps: the world and the counters that seed captures.
struct BulletCellState final : CellState {
  const void* owner = nullptr;
  PhysicsSnapshot world;
  std::uint64_t seed = 0;
  int captures = 0;
  int attempts = 0;
  int placed = 0;
};

bool is_rotation(const Eigen::Matrix3d& r) {
  return r.allFinite() && (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() < 1e-3 &&
         r.determinant() > 0.0;
}

double in_range(const Parameters& p, const std::string& key, double fallback, double lo,
                double hi) {
  const double value = p.get<double>(key, fallback);
  if (!(value >= lo && value <= hi))
    p.fail(key,
           "'" + key + "' must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return value;
}

SceneSpec read_scene_parameter(const Parameters& params) {
  const std::string path = params.require<std::string>("scene");
  try {
    return read_scene(resolve_path(path, params.file()));
  } catch (const Error& error) {
    if (std::string(error.what()).find(path) != std::string::npos) throw;
    params.fail("scene", std::string("scene: ") + error.what());
  }
}

// `objects: FOLDER` swaps the scene's objects for meshes drawn from FOLDER (as many as the
// scene places), so one scene layout serves every object set.
void replace_objects(const Parameters& params, SceneSpec& scene) {
  const std::string folder = params.get<std::string>("objects", "");
  if (folder.empty()) return;
  const std::string resolved = resolve_path(folder, params.file());
  if (!std::filesystem::is_directory(resolved)) {
    params.fail("objects", "objects: '" + folder + "' is not a folder of object meshes");
  }
  const int count = std::max<int>({1, scene.random.count, static_cast<int>(scene.objects.size())});
  scene.objects.clear();
  scene.random.count = count;
  scene.random.shapes.clear();
  scene.random.names.clear();
  scene.random.folder = resolved;
}

// `object: {...}` (one listed object, as in a scene's `objects`) replaces the scene's objects:
// how the isolation benchmark puts one object in one pose into a layout.
void replace_with_object(const Parameters& params, SceneSpec& scene) {
  if (!params.has("object")) {
    params.child("object");  // known either way
    return;
  }
  if (params.has("objects")) params.fail("object", "give 'object' or 'objects', not both");
  const Parameters object = params.child("object");
  scene.objects = {parse_object(object, params.file())};
  scene.random = RandomObjects{};
}

// `object_count: N` drops N random objects instead of the scene's number (a clutter run of
// another size with the same layout).
void replace_object_count(const Parameters& params, SceneSpec& scene) {
  if (!params.has("object_count")) return;
  const int count = params.get<int>("object_count", 0);
  if (count < 1 || count > 100) params.fail("object_count", "'object_count' must be in [1, 100]");
  if (scene.random.count == 0)
    params.fail("object_count", "'object_count' needs a scene with random objects");
  scene.random.count = count;
}

SceneSpec scene_of(const Parameters& params) {
  SceneSpec scene = read_scene_parameter(params);
  replace_objects(params, scene);
  replace_with_object(params, scene);
  replace_object_count(params, scene);
  return scene;
}

}  // namespace

CellOptions read_cell_options(const Parameters& p, const SceneSpec& scene) {
  CellOptions o;
  o.seed = p.get<std::uint64_t>("seed", scene.seed);
  o.sensor.scale = in_range(p, "noise", 1.0, 0.0, 10.0);
  const std::string sensor = p.get<std::string>("sensor", "primesense");
  if (sensor == "dexnet")
    o.sensor.kind = SensorKind::kDexNet;
  else if (sensor != "primesense")
    p.fail("sensor", "parameter 'sensor' must be primesense or dexnet, got '" + sensor + "'");
  o.render_threads = int(in_range(p, "render_threads", o.render_threads, 1, 64));
  o.physics.time_step_s = 1.0 / in_range(p, "physics_hz", 240.0, 60.0, 2000.0);
  o.physics.solver_iterations = int(in_range(p, "solver_iterations", 50, 1, 1000));
  AttemptOptions& a = o.attempt;
  a.standoff_m = in_range(p, "standoff_m", a.standoff_m, 0.0, 0.5);
  a.approach_step_m = in_range(p, "approach_step_m", a.approach_step_m, 0.0005, 0.02);
  a.lift_m = in_range(p, "lift_m", a.lift_m, 0.02, 0.5);
  a.hold_s = in_range(p, "hold_s", a.hold_s, 0.0, 10.0);
  o.execution.position_m = in_range(p, "execution_noise_m", 0.0, 0.0, 0.05);
  o.execution.rotation_rad = in_range(p, "execution_noise_rad", 0.0, 0.0, 0.5);
  o.execution.seed = p.get<std::uint64_t>("execution_seed", 0);
  a.gripper.finger_force_n = in_range(p, "finger_force_n", a.gripper.finger_force_n, 0.1, 500.0);
  a.gripper.friction = in_range(p, "gripper_friction", a.gripper.friction, 0.05, 1.0);
  a.gripper.torsional_friction_m =
      in_range(p, "gripper_torsional_friction_m", a.gripper.torsional_friction_m, 0.0, 0.05);
  a.gripper.hand_force_n = in_range(p, "hand_force_n", a.gripper.hand_force_n, 1.0, 5000.0);
  if (p.has("robot")) {
    const RobotFile robot = robot_file_parameter(p, "robot");
    CellArmOptions arm;
    arm.robot_file = robot.urdf_path;
    arm.tip = robot.arm_tip;
    arm.home_rad = p.get<std::vector<double>>("home_rad", robot.home_rad);
    o.arm = arm;
  } else if (p.has("home_rad")) {
    p.fail("home_rad", "'home_rad' needs 'robot' (the arm's robot file)");
  }
  return o;
}

namespace {

// The arm of `options` (none without one), its errors located at the keys that name them.
std::shared_ptr<const CellArm> arm_of(const Parameters& params, const CellOptions& options) {
  try {
    if (options.arm) return std::make_shared<const CellArm>(*options.arm);
  } catch (const CellArm::HomeError& e) {
    params.fail("home_rad", e.what());
  } catch (const Error& e) {
    params.fail("robot", std::string("robot: ") + e.what());
  }
  return nullptr;
}

}  // namespace

BulletCell::BulletCell(const Parameters& params) : scene_(scene_of(params)) {
  options_ = read_cell_options(params, scene_);
  params.reject_unknown();
  arm_ = arm_of(params, options_);
  reset(options_.seed);
}

void BulletCell::check_parameters(const Parameters& params) {
  const CellOptions options = read_cell_options(params, scene_of(params));
  params.reject_unknown();
  (void)arm_of(params, options);
}

BulletCell::BulletCell(SceneSpec scene, const CellOptions& options)
    : scene_(std::move(scene)), options_(options) {
  if (options_.arm) arm_ = std::make_shared<const CellArm>(*options_.arm);
  reset(options_.seed);
}

JointState BulletCell::arm_state() const { return arm_ ? arm_->home() : JointState{}; }

std::vector<int> BulletCell::objects_in_workspace() const {
  const bool has_box = scene_.box.present && !scene_.box.removed_after_drop;
  std::vector<int> ids;
  for (const int id : objects()) {
    const Eigen::Vector3d p = world_->pose(id).translation();
    if (p.z() < scene_.table.top_z_m - 0.01) continue;  // about to be removed as fallen
    if (has_box && !inside_box(scene_.box, p)) continue;
    ids.push_back(id);
  }
  return ids;
}

std::vector<ObjectTruth> BulletCell::object_truth() const {
  std::vector<ObjectTruth> truth;
  for (const int id : objects_in_workspace()) {
    ObjectTruth object{world_->name(id), world_->pose(id), 0.0};
    if (const auto mesh = world_->visual(id)) {
      std::vector<Eigen::Vector3d> vertices;
      vertices.reserve(mesh->vertices.size());
      for (const Eigen::Vector3f& v : mesh->vertices)
        vertices.push_back(object.X_BaseObject * v.cast<double>());
      object.narrowest_horizontal_m = narrowest_horizontal_extent_m(vertices);
    }
    truth.push_back(std::move(object));
  }
  return truth;
}

std::vector<std::string> BulletCell::view_names() const {
  std::vector<std::string> names;
  for (const auto& camera : scene_.cameras) names.push_back(camera.name);
  return names;
}

Cloud BulletCell::capture(const std::vector<std::string>& views) {
  if (views.size() > 32) throw Error("a cloud holds at most 32 views");
  renderer_.set_scene(world_->visuals());
  const RandomStream random = RandomStream(seed_).derive(1000 + std::uint64_t(captures_++));
  Cloud cloud;
  for (std::size_t v = 0; v < views.size(); ++v) {
    const CameraSpec* camera = nullptr;
    for (const auto& c : scene_.cameras)
      if (c.name == views[v]) camera = &c;
    if (!camera) throw Error("the cell has no view '" + views[v] + "'");
    renderer_.render(*camera, options_.sensor, random.derive(v), std::uint32_t(v), cloud,
                     options_.render_threads);
    cloud.view_origins_m.push_back(camera->position_m.cast<float>());
  }
  return cloud;
}

GraspAttempt BulletCell::execute(const GraspRequest& request) {
  const Hand& grasp = request.grasp;
  GraspAttempt refused;
  refused.X_BaseHand_planned = grasp.X_FrameHand;
  if (grasp.frame != "base") {
    refused.reason = "the grasp is in frame '" + grasp.frame + "', the cell needs 'base'";
    return refused;
  }
  if (!is_rotation(grasp.X_FrameHand.linear()) || !grasp.X_FrameHand.translation().allFinite()) {
    refused.reason = "the grasp pose is not a rigid motion";
    return refused;
  }
  try {
    request.gripper.validate();
  } catch (const Error& error) {
    refused.reason = error.message();
    return refused;
  }
  if (!request.trajectory.empty()) {
    GraspOutcome outcome = GraspOutcome::kNotExecuted;
    const std::string why = follow_trajectory(request, &outcome);
    if (!why.empty()) {
      refused.outcome = outcome;
      refused.reason = why;
      if (outcome != GraspOutcome::kNotExecuted) ++attempts_;
      return refused;
    }
  }
  ++attempts_;
  AttemptOptions attempt = options_.attempt;
  attempt.gripper.geometry = request.gripper;
  const std::vector<int> before = objects_in_workspace();
  const Eigen::Isometry3d X_BaseHand =
      executed_pose(grasp.X_FrameHand, options_.execution, seed_, attempts_);
  AttemptResult result = attempt_grasp(*world_, X_BaseHand, attempt);
  GraspAttempt& record = result.record;
  if (record.outcome == GraspOutcome::kSuccess) world_->remove_body(result.held_object);
  world_->settle(1.0);
  const std::vector<std::string> out = names_gone(before, result.held_object);
  remove_fallen_objects();
  std::string names;
  for (const auto& name : out) names += (names.empty() ? "" : ", ") + name;
  if (record.outcome == GraspOutcome::kSuccess && !out.empty()) {
    record.reason += "; out of the workspace with it: " + names;  // still a success
  } else if (record.outcome != GraspOutcome::kCollisionOnApproach && !out.empty()) {
    record.outcome = GraspOutcome::kObjectKnockedOut;
    record.reason += "; knocked out of the workspace: " + names;
  }
  return record;
}

std::vector<std::string> BulletCell::names_gone(const std::vector<int>& before, int held) const {
  const std::vector<int> now = objects_in_workspace();
  std::vector<std::string> names;
  for (const int id : before)
    if (id != held && std::find(now.begin(), now.end(), id) == now.end())
      names.push_back(world_->name(id) +
                      (world_->pose(id).translation().z() < scene_.table.top_z_m - 0.01
                           ? " (off the table)"
                           : " (out of the box)"));
  return names;
}

std::string BulletCell::follow_trajectory(const GraspRequest& request,
                                          GraspOutcome* outcome) const {
  *outcome = GraspOutcome::kNotExecuted;
  if (!arm_) return "the cell has no arm to follow a trajectory (set the cell's 'robot')";
  const Trajectory& t = request.trajectory;
  if (std::string why = arm_->check_trajectory(t); !why.empty()) return why;
  const std::vector<double>& start = t.positions_rad.front();
  const std::vector<double> home = arm_->home().positions_rad;
  for (std::size_t j = 0; j < home.size(); ++j)
    if (std::abs(start[j] - home[j]) > 1e-3)
      return "the trajectory starts away from the arm's state (" + arm_->joint_names()[j] + ")";
  const Eigen::Isometry3d X_BaseTip = arm_->tip_pose(t.positions_rad.back());
  const double off_m = (X_BaseTip.translation() - request.grasp.X_FrameHand.translation()).norm();
  const double off_rad =
      Eigen::AngleAxisd(X_BaseTip.linear().transpose() * request.grasp.X_FrameHand.linear())
          .angle();
  if (off_m > 0.005 || off_rad > 0.05)
    return "the trajectory ends " + std::to_string(int(std::round(off_m * 1000))) + " mm and " +
           std::to_string(int(std::round(off_rad * 180 / M_PI))) + " deg from the grasp";
  if (const auto contact = arm_->first_contact(t, *world_)) {
    *outcome = GraspOutcome::kArmCollision;
    return "the arm's " + contact->link + " touched " + contact->body + " on segment " +
           std::to_string(contact->segment + 1) + " of " +
           std::to_string(t.positions_rad.size() - 1) + " of its motion";
  }
  return "";
}

void BulletCell::remove_fallen_objects() {
  for (int id : objects())
    if (world_->pose(id).translation().z() < scene_.table.top_z_m - 0.01) world_->remove_body(id);
}

void BulletCell::reset(std::uint64_t seed) {
  seed_ = seed;
  captures_ = 0;
  attempts_ = 0;
  world_ = std::make_unique<PhysicsWorld>(options_.physics);
  placed_ = int(build_scene(scene_, seed, meshes_, *world_).size());
}

std::shared_ptr<const CellState> BulletCell::save() const {
  auto state = std::make_shared<BulletCellState>();
  state->owner = this;
  state->world = world_->snapshot();
  state->seed = seed_;
  state->captures = captures_;
  state->attempts = attempts_;
  state->placed = placed_;
  return state;
}

void BulletCell::restore(const CellState& state) {
  const auto* saved = dynamic_cast<const BulletCellState*>(&state);
  if (saved == nullptr || saved->owner != this)
    throw Error("bullet_cell: the state to restore was saved by another cell");
  world_->restore(saved->world);
  seed_ = saved->seed;
  captures_ = saved->captures;
  attempts_ = saved->attempts;
  placed_ = saved->placed;
}

}  // namespace antipode::cells
