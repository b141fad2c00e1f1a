#include "antipode/robot/robot_file.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"
#include "antipode/core/yaml_limits.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/robot/robot_model.hpp"

namespace antipode {
namespace {

bool is_urdf(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  return extension == ".urdf" || extension == ".xml";
}

YAML::Node load_map(const std::string& path, const std::string& what) {
  if (is_urdf(path)) {
    throw Error(what + ": a URDF, not a robot file", {},
                "name the robot file that names this URDF, its grasp frame and its home (for "
                "example robots/baxter/baxter.yaml; docs/robot.md, \"Bringing your own robot\")");
  }
  return load_yaml_map(path, what, "robot keys", "robots/*/");
}

// The link `key` names, which must be on `chain_links` (the arm from the root to its tip).
std::string link_on_arm(const Parameters& p, const char* key, const RobotModel& robot,
                        const std::vector<std::string>& chain_links) {
  std::string link = p.require<std::string>(key);
  if (!robot.has_link(link)) {
    p.fail(key, std::string(key) + ": no link '" + link + "' in " + robot.source() +
                    did_you_mean(link, robot.link_names()));
  }
  for (const std::string& on_arm : chain_links)
    if (on_arm == link) return link;
  p.fail(key, std::string(key) + ": link '" + link + "' is not on the arm (" + chain_links.front() +
                  " ... " + chain_links.back() + ")");
}

RobotModel load_urdf(const Parameters& p, const std::string& urdf_path) {
  try {
    return RobotModel::load(urdf_path);
  } catch (const Error& e) {
    p.fail("urdf", "urdf: " + e.message());
  }
}

std::vector<double> home_of(const Parameters& p, const KinematicChain& arm) {
  auto home = p.require<std::vector<double>>("home_rad");
  if (home.size() != arm.dof()) {
    p.fail("home_rad", "home_rad: " + std::to_string(home.size()) + " values for the " +
                           std::to_string(arm.dof()) + " joints of the arm (" +
                           arm.joint_names().front() + " ... " + arm.joint_names().back() + ")");
  }
  Eigen::VectorXd q(home.size());
  for (std::size_t i = 0; i < home.size(); ++i) q[Eigen::Index(i)] = home[i];
  if (!q.allFinite() || !arm.within_limits(q, 1e-9)) {
    for (std::size_t i = 0; i < home.size(); ++i) {
      const JointLimits& limits = arm.limits()[i];
      if (!(home[i] >= limits.lower - 1e-9 && home[i] <= limits.upper + 1e-9)) {
        p.fail("home_rad", "home_rad: " + arm.joint_names()[i] + " = " + std::to_string(home[i]) +
                               " is outside its limits [" + std::to_string(limits.lower) + ", " +
                               std::to_string(limits.upper) + "]");
      }
    }
  }
  return home;
}

}  // namespace

RobotFile read_robot_file(const std::string& path) {
  const std::string what = "robot file '" + path + "'";
  const YAML::Node root = load_map(path, what);
  const Parameters p(root, what, path);
  RobotFile file;
  file.path = path;
  file.urdf_path = resolve_path(p.require<std::string>("urdf"), path);
  const RobotModel robot = load_urdf(p, file.urdf_path);
  file.name = p.get<std::string>("name", robot.name());
  file.arm_tip = p.require<std::string>("arm_tip");
  if (!robot.has_link(file.arm_tip)) {
    p.fail("arm_tip", "arm_tip: no link '" + file.arm_tip + "' in " + file.urdf_path +
                          did_you_mean(file.arm_tip, robot.link_names()));
  }
  const KinematicChain arm = robot.chain(robot.root_link(), file.arm_tip);
  if (arm.dof() == 0) p.fail("arm_tip", "arm_tip: no moving joint between the root and it");
  file.gripper_from = link_on_arm(p, "gripper_from", robot, arm.link_names());
  if (robot.chain(file.gripper_from, file.arm_tip).dof() != 0) {
    p.fail("gripper_from", "gripper_from: joints move between '" + file.gripper_from +
                               "' and the grasp frame; name the hand's first link, past the "
                               "arm's last joint");
  }
  if (robot.root_link() != "base") {
    p.fail("urdf", "urdf: the root link of " + file.urdf_path + " is '" + robot.root_link() +
                       "'; clouds and grasps are in the cell's frame 'base': name the root "
                       "link base (docs/robot.md, \"Bringing your own robot\")");
  }
  file.home_rad = home_of(p, arm);
  file.points_unchecked = p.get<std::vector<std::string>>("points_unchecked", {file.gripper_from});
  for (const std::string& link : file.points_unchecked) {
    if (!robot.has_link(link)) {
      p.fail("points_unchecked", "points_unchecked: no link '" + link + "' in " + file.urdf_path +
                                     did_you_mean(link, robot.link_names()));
    }
  }
  file.gripper_path = resolve_path(p.require<std::string>("gripper"), path);
  try {
    file.gripper = read_gripper_file(file.gripper_path).geometry;
  } catch (const Error& e) {
    if (e.where().known()) throw;  // located in the gripper file
    p.fail("gripper", "gripper: " + e.message());
  }
  if (p.has("model")) file.model_path = resolve_path(p.require<std::string>("model"), path);
  if (p.has("success_model"))
    file.success_model_path = resolve_path(p.require<std::string>("success_model"), path);
  p.reject_unknown();
  return file;
}

RobotFile robot_file_parameter(const Parameters& params, const std::string& key) {
  const std::string path = resolve_path(params.require<std::string>(key), params.file());
  try {
    return read_robot_file(path);
  } catch (const Error& error) {
    if (error.where().known()) throw;  // located in the robot file
    params.fail(key, key + ": " + error.message() +
                         (error.hint().empty() ? std::string() : " (" + error.hint() + ")"));
  }
}

}  // namespace antipode
