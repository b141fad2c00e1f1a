#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"
#include "json_output.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Writes a planned arm motion as where the arm's links are along it, all or nothing, for a
/// viewer to draw: {"frame": "base", "links": [names, base to tip], "waypoints": [{"time_s",
/// "joints_rad", "links_m": [[x, y, z] of each link's origin]}]}, by forward kinematics of
/// the chain of the robot file's arm. An empty `file` writes nothing.
class WriteArmPath final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"WriteArmPath",
            bt::NodeCategory::kAction,
            {bt::input_port<Trajectory>("trajectory", "the arm's motion (PlanReach)"),
             bt::input_port<std::string>("robot", "the robot file (robots/*/*.yaml)"),
             bt::input_port<std::string>("file", std::string(), "output JSON file; empty = none")},
            0,
            0,
            "Writes where an arm's links pass along a planned motion to a JSON file.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const Trajectory& trajectory = get_input_ref<Trajectory>("trajectory");
    const RobotFile robot_file =
        read_robot_file(resolve_path(get_input<std::string>("robot"), where().file));
    const RobotModel robot = RobotModel::load(robot_file.urdf_path);
    const KinematicChain arm = robot.chain(robot.root_link(), robot_file.arm_tip);
    if (trajectory.joint_names != arm.joint_names())
      fail("trajectory", "the trajectory's joints are not those of " + robot_file.name + "'s arm");
    nlohmann::ordered_json waypoints = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < trajectory.positions_rad.size(); ++k) {
      nlohmann::ordered_json links = nlohmann::ordered_json::array();
      for (const Eigen::Isometry3d& X : arm.link_poses(joint_vector(trajectory.positions_rad[k])))
        links.push_back({X.translation().x(), X.translation().y(), X.translation().z()});
      waypoints.push_back({{"time_s", k < trajectory.times_s.size() ? trajectory.times_s[k] : 0.0},
                           {"joints_rad", trajectory.positions_rad[k]},
                           {"links_m", std::move(links)}});
    }
    const nlohmann::ordered_json document = {{"frame", robot.root_link()},
                                             {"links", arm.link_names()},
                                             {"waypoints", std::move(waypoints)}};
    write_json_file(file, document);
    log(std::to_string(trajectory.positions_rad.size()) + " waypoints written to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_write_arm_path(bt::NodeRegistry& registry) { registry.register_node<WriteArmPath>(); }

}  // namespace antipode::pipeline
