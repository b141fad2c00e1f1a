// CheckRobot: the checks of a robot file (robot_check.hpp), printed as a report a robot's
// author reads top to bottom, and written as JSON. Fails, naming the first problem, when a
// check fails.
#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/core/atomic_file.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/robot/robot_file.hpp"
#include "robot_check.hpp"

namespace antipode::robot_nodes {
namespace {

using collision::RobotCheck;

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string percent(int part, int whole) {
  return fixed(100.0 * part / std::max(1, whole), 1) + "%";
}

std::vector<std::string> report_lines(const RobotCheck& c, const RobotFile& file) {
  std::vector<std::string> lines;
  const auto& arm = c.arm;
  lines.push_back(c.name + " (" + file.path + "): arm '" + arm.base_link() + "' -> '" +
                  arm.tip_link() + "', " + std::to_string(arm.dof()) + " joints");
  for (std::size_t i = 0; i < arm.dof(); ++i) {
    const JointLimits& l = arm.limits()[i];
    lines.push_back("  " + arm.joint_names()[i] + ": [" + fixed(l.lower, 4) + ", " +
                    fixed(l.upper, 4) + "] rad, " + fixed(l.velocity, 3) + " rad/s");
  }
  const Eigen::Vector3d p = c.X_BaseGrasp_home.translation();
  const Eigen::Vector3d a = c.X_BaseGrasp_home.linear().col(0);
  lines.push_back("forward kinematics: at home the grasp frame is at (" + fixed(p.x(), 3) + ", " +
                  fixed(p.y(), 3) + ", " + fixed(p.z(), 3) + ") m, approaching along (" +
                  fixed(a.x(), 2) + ", " + fixed(a.y(), 2) + ", " + fixed(a.z(), 2) +
                  "); it reaches up to " + fixed(c.reach_m, 3) + " m from the first moving joint");
  lines.push_back("self-collision (" + std::to_string(c.self_pairs) + " link pairs): home " +
                  c.home_contact + "; " + std::to_string(c.self_colliding) + " of " +
                  std::to_string(c.configurations) + " random configurations (" +
                  percent(c.self_colliding, c.configurations) + ") collide, first pairs found:");
  for (std::size_t i = 0; i < c.pairs.size() && i < 10; ++i)
    lines.push_back("  " + std::to_string(c.pairs[i].count) + "  " + c.pairs[i].link + " with " +
                    c.pairs[i].other);
  for (const auto& grid : c.reach) {
    std::string line =
        "reach from above, " + grid.region + ": " + std::to_string(grid.points_reachable) + " of " +
        std::to_string(grid.points) + " points (" + percent(grid.points_reachable, grid.points) +
        "; " + std::to_string(grid.points_hand_blocked) + " where only the hand does not fit), " +
        std::to_string(grid.reachable) + " of " + std::to_string(grid.grasps) +
        " grasps (4 closing directions each)";
    for (const auto& [status, count] : grid.failures)
      line += "; " + status + " " + std::to_string(count);
    lines.push_back(line);
  }
  lines.push_back("gripper: the URDF's fingers against " + file.gripper_path + ":");
  for (const auto& m : c.gripper)
    lines.push_back("  " + m.quantity + ": URDF " + fixed(m.urdf_m, 4) + " m, file " +
                    fixed(m.file_m, 4) + " m" +
                    (m.ok         ? ""
                     : m.required ? "  <- does not match"
                                  : "  (differs)"));
  lines.push_back(c.problems.empty() ? "all checks passed"
                                     : std::to_string(c.problems.size()) + " problem(s):");
  for (const std::string& problem : c.problems) lines.push_back("  " + problem);
  return lines;
}

nlohmann::ordered_json to_json(const RobotCheck& c, const RobotFile& file) {
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  for (const auto& pair : c.pairs)
    pairs.push_back({{"link", pair.link}, {"other", pair.other}, {"count", pair.count}});
  nlohmann::ordered_json reach = nlohmann::ordered_json::array();
  for (const auto& g : c.reach)
    reach.push_back({{"region", g.region},
                     {"points", g.points},
                     {"points_reachable", g.points_reachable},
                     {"points_hand_blocked", g.points_hand_blocked},
                     {"grasps", g.grasps},
                     {"reachable", g.reachable},
                     {"failures", g.failures}});
  nlohmann::ordered_json gripper = nlohmann::ordered_json::array();
  for (const auto& m : c.gripper)
    gripper.push_back({{"quantity", m.quantity},
                       {"urdf_m", m.urdf_m},
                       {"file_m", m.file_m},
                       {"required", m.required},
                       {"ok", m.ok}});
  const Eigen::Vector3d p = c.X_BaseGrasp_home.translation();
  return {{"robot", file.path},
          {"name", c.name},
          {"joints", c.arm.joint_names()},
          {"home_grasp_m", {p.x(), p.y(), p.z()}},
          {"reach_m", c.reach_m},
          {"self_collision",
           {{"pairs_checked", c.self_pairs},
            {"home", c.home_contact},
            {"configurations", c.configurations},
            {"colliding", c.self_colliding},
            {"first_pairs", pairs}}},
          {"reach", reach},
          {"gripper", gripper},
          {"problems", c.problems}};
}

class CheckRobot final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {
        "CheckRobot",
        bt::NodeCategory::kAction,
        {bt::input_port<std::string>("robot", "the robot file (robots/*/*.yaml)"),
         bt::input_port<std::string>("scene", std::string(),
                                     "a cell scene whose table and box the reach grids cover; "
                                     "empty = no reach grid"),
         bt::input_port<int>("configurations", 1000, "random configurations for self-collision"),
         bt::input_port<std::string>("report", std::string(), "JSON report file; empty = none")},
        0,
        0,
        "Checks a robot file: kinematics, limits, self-collision, reach and the gripper.",
        {}};
  }

 protected:
  bt::Status tick() override {
    const RobotFile file =
        read_robot_file(resolve_path(get_input<std::string>("robot"), where().file));
    collision::RobotCheckOptions options;
    const std::string scene = get_input<std::string>("scene");
    options.scene_path = scene.empty() ? scene : resolve_path(scene, where().file);
    options.configurations = get_input<int>("configurations");
    if (options.configurations < 1) fail("configurations", "configurations must be at least 1");
    // The configurations follow the tree's seed (`--seed`), as every random stream does.
    options.seed = std::uint64_t(random().uniform() * 9007199254740992.0);
    const RobotCheck check = collision::check_robot(file, options);
    for (const std::string& line : report_lines(check, file)) log(line);
    const std::string report = get_input<std::string>("report");
    if (!report.empty()) {
      write_file_atomically(report, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << to_json(check, file).dump(1) << "\n";
        out.close();
        if (!out) throw Error("write failed");
      });
    }
    if (check.problems.empty()) return bt::Status::kSuccess;
    set_failure_reason(check.problems.front());
    return bt::Status::kFailure;
  }
};

}  // namespace

void register_check_robot(bt::NodeRegistry& registry) { registry.register_node<CheckRobot>(); }

}  // namespace antipode::robot_nodes
