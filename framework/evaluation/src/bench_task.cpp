#include "antipode/evaluation/bench_task.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>

#include "antipode/bt/loader.hpp"
#include "antipode/core/error.hpp"
#include "antipode/evaluation/stage_timer.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode::evaluation {
namespace {

std::string yaml_list(const std::vector<std::string>& items) {
  std::string text = "[";
  for (std::size_t i = 0; i < items.size(); ++i) text += (i ? ", " : "") + items[i];
  return text + "]";
}

std::string number(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// DIR/VARIANT-OBJECT-poseK + suffix for `task`, or "" without DIR: where the tree draws the
// task when it fails (--pictures) and writes its selection, cloud and objects (--selections).
std::string task_file(const std::string& dir, const BenchTask& task, const std::string& suffix) {
  if (dir.empty()) return "";
  return (std::filesystem::path(dir) / (task.variant->name + "-" + task.object.name + "-pose" +
                                        std::to_string(task.pose) + suffix))
      .string();
}

// The --set entries that make the tree run `task`, the user's last.
std::vector<std::pair<std::string, std::string>> task_overrides(const TaskSettings& settings,
                                                                const BenchTask& task) {
  const Eigen::Vector3d rpy = pose_rpy(task.pose, task.poses);
  const std::string threads = std::to_string(settings.threads);
  std::vector<std::pair<std::string, std::string>> entries = {
      {"cell.object", "{" + task.object.spec_yaml + ", rpy_rad: [" + number(rpy.x()) + ", " +
                          number(rpy.y()) + ", " + number(rpy.z()) + "]}"},
      {"cell.seed", std::to_string(task.seed)},
      {"cell.render_threads", threads},
      {"sampler.threads", threads},
      {"selector.threads", threads},
      {"views", yaml_list(task.variant->views)},
      {"picture_file", task_file(settings.pictures_dir, task, ".png")},
      {"selection_file", task_file(settings.selections_dir, task, ".json")},
      {"cloud_file", task_file(settings.selections_dir, task, ".pcd")},
      {"objects_file", task_file(settings.selections_dir, task, "-objects.json")}};
  if (!settings.noise.empty()) entries.emplace_back("cell.noise", settings.noise);
  if (!task.variant->classifier_plugin.empty())
    entries.emplace_back("classifier.plugin", task.variant->classifier_plugin);
  if (task.variant->classifier_threads) entries.emplace_back("classifier.threads", threads);
  for (auto& entry : parse_overrides(settings.overrides)) entries.push_back(std::move(entry));
  return entries;
}

std::vector<double> vector_of(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// How many hands each stage passed on: hypotheses, hands classified as grasps, and the
// selection's reasons (what became of every classified hand).
nlohmann::ordered_json funnel(const bt::Blackboard& board) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  const auto count_of = [&](const char* key) {
    return board.get_ref<HandSetPtr>(key)->hands.size();
  };
  if (board.has("hands")) out["hypotheses"] = count_of("hands");
  if (board.has("classified")) {
    std::size_t positive = 0;
    for (const Hand& hand : board.get_ref<HandSetPtr>("classified")->hands)
      positive += hand.rejection == Rejection::kNone ? 1 : 0;
    out["grasps_classified"] = positive;
  }
  if (board.has("grasps")) {
    nlohmann::ordered_json reasons = nlohmann::ordered_json::object();
    for (const Hand& hand : board.get_ref<HandSetPtr>("grasps")->hands) {
      const std::string reason = rejection_reason(hand);
      reasons[reason] = reasons.value(reason, 0) + 1;
    }
    out["selection"] = reasons;
  }
  return out;
}

}  // namespace

nlohmann::ordered_json hand_json(const Hand& hand) {
  const Eigen::Quaterniond q(hand.X_FrameHand.linear());
  return {{"position_m", vector_of(hand.position_m())},
          {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
          {"approach", vector_of(hand.approach())},
          {"score", hand.score},
          {"width_m", hand.width_m}};
}

nlohmann::ordered_json record_json(const GraspAttempt& r) {
  const auto finite_or_null = [](double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
  };
  return {{"reached_pose", r.reached_pose},
          {"pose_error_m", finite_or_null(r.pose_error_m)},
          {"stopped_by", r.stopped_by},
          {"first_contact", r.first_contact},
          {"first_contact_before_pose_m", finite_or_null(r.first_contact_before_pose_m)},
          {"opening_at_contact_m", finite_or_null(r.opening_at_contact_m)},
          {"between_fingers_at_detection", r.between_fingers_at_detection},
          {"between_fingers_at_closing", r.between_fingers_at_closing},
          {"in_collision_at_planned_pose", r.in_collision_at_planned_pose},
          {"touching_at_closing", r.touching_at_closing},
          {"pinched_object", r.pinched_object},
          {"lift_m", r.lift_m},
          {"duration_s", r.duration_s}};
}

std::string failure_class(const GraspAttempt& r) {
  switch (r.outcome) {
    case GraspOutcome::kSuccess:
      return "success";
    case GraspOutcome::kCollisionOnApproach:
      return "collision at the stand-off pose";
    case GraspOutcome::kArmCollision:
      return "arm collision";
    case GraspOutcome::kNotExecuted:
      return "not executed";
    default:
      break;
  }
  if (!r.in_collision_at_planned_pose.empty()) return "planned into the object";
  if (!r.reached_pose) return "stopped short of the pose";
  if (r.between_fingers_at_detection.empty()) return "nothing between the planned fingers";
  if (r.outcome == GraspOutcome::kEmptyGrasp) return "closed on nothing";
  if (r.outcome == GraspOutcome::kObjectKnockedOut) return "knocked out";
  return "slipped";
}

const std::vector<BenchVariant>& isolation_variants() {
  static const std::vector<BenchVariant> variants = {
      {"nc_1v", "passthrough_classifier", false, {"left"}},
      {"nc_2v", "passthrough_classifier", false, {"left", "right"}},
      {"a_2v", "antipodal_classifier", true, {"left", "right"}},
      {"svm_1v", "", true, {"left"}},
      {"svm_2v", "", true, {"left", "right"}},
  };
  return variants;
}

void require_cell_component(const std::string& tree_path, const std::string& example_tree) {
  YAML::Node tree;
  try {
    tree = YAML::LoadFile(tree_path);
  } catch (const YAML::Exception&) {
    return;  // loading the tree reports the file's own errors, with their lines
  }
  if (tree.IsMap() && tree["components"] && tree["components"].IsMap() &&
      tree["components"]["cell"])
    return;
  throw Error("--tree: '" + tree_path + "' has no component 'cell': a bench resets and reads " +
              "the simulated cell through it, as " + example_tree + " does");
}

bt::Tree load_task_tree(const Session& session, const TaskSettings& settings,
                        const BenchTask& task) {
  bt::LoadOptions load;
  load.registry = &session.registry;
  load.components = session.host.get();
  load.seed = task.seed;
  load.overrides = task_overrides(settings, task);
  load.main_tree = "attempt";
  return bt::load_tree_string(settings.tree_yaml, settings.tree_path, load);
}

nlohmann::ordered_json run_task(const Session& session, const TaskSettings& settings,
                                const BenchTask& task) {
  nlohmann::ordered_json out = {
      {"task", task.index},          {"attempt", task.attempt},       {"object", task.object.name},
      {"pose", task.pose},           {"variant", task.variant->name}, {"seed", task.seed},
      {"graspable", task.graspable}, {"held_out", task.held_out}};
  const auto start = std::chrono::steady_clock::now();
  bt::Tree tree = load_task_tree(session, settings, task);
  tree.set_log_sink([](const bt::Node&, const std::string&) {});
  StageTimer timer;
  tree.add_observer(&timer);
  timer.start();
  try {
    tree.tick_while_running(std::chrono::milliseconds(0));
    const bt::Blackboard& board = tree.blackboard();
    out["outcome"] = board.has("outcome") ? board.text("outcome") : "no grasp found";
    if (board.has("attempt")) {
      const GraspAttempt& record = board.get_ref<GraspAttempt>("attempt");
      out["reason"] = failure_class(record);
      out["detail"] = record.reason;
      out["hand"] = hand_json(board.get_ref<Hand>("grasp"));
      out["record"] = record_json(record);
    } else {
      // "no grasp found", or the tree's reason such as "no motion plan".
      out["reason"] = out["outcome"];
      out["detail"] = timer.first_failure();
    }
    out["funnel"] = funnel(board);
  } catch (const std::exception& error) {
    out["outcome"] = "error";
    out["reason"] = "error";
    out["detail"] = error.what();
  }
  out["stage_s"] = timer.seconds();
  out["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  tree.remove_observer(&timer);
  return out;
}

}  // namespace antipode::evaluation
