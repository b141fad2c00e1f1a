#include "robot_check.hpp"

#include <algorithm>
#include <cstdio>

#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"

namespace antipode::collision {
namespace {

Eigen::VectorXd vector_of(const std::vector<double>& values) {
  Eigen::VectorXd q(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) q[Eigen::Index(i)] = values[i];
  return q;
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

// Self-collision at home and at random configurations: the first pair found in each.
void check_self_collision(RobotCheck& check, const RobotModel& robot, const RobotFile& file,
                          const RobotCheckOptions& o) {
  const ArmCollisionWorld world(robot, check.arm);
  check.self_pairs = world.self_pairs().size();
  check.home_contact = world.check(vector_of(file.home_rad)).str();
  if (check.home_contact != "free")
    check.problems.push_back("the home configuration is in " + check.home_contact);
  std::map<std::pair<std::string, std::string>, int> counts;
  RandomStream random(o.seed);
  for (int k = 0; k < o.configurations; ++k) {
    const ContactReport contact = world.check(check.arm.random_configuration(random));
    if (contact.kind != ContactReport::Kind::kSelf) continue;
    ++check.self_colliding;
    ++counts[{contact.link, contact.other}];
  }
  check.configurations = o.configurations;
  for (const auto& [pair, count] : counts) check.pairs.push_back({pair.first, pair.second, count});
  std::stable_sort(check.pairs.begin(), check.pairs.end(),
                   [](const PairCount& a, const PairCount& b) { return a.count > b.count; });
  // A pair in contact in most configurations is two shapes that overlap whatever the joints
  // do: a shape too big, or misplaced.
  for (const PairCount& pair : check.pairs)
    if (2 * pair.count > o.configurations)
      check.problems.push_back(pair.link + " and " + pair.other + " collide in " +
                               format("%.0f%% of random configurations: a shape is too big or "
                                      "misplaced",
                                      100.0 * pair.count / o.configurations));
}

// The farthest the grasp frame gets from the first moving joint, over random configurations.
double farthest_reach(const KinematicChain& arm, const RobotModel& robot, std::uint64_t seed) {
  const std::vector<std::string> links = arm.link_names();
  std::size_t first = 0;
  for (; first < links.size(); ++first) {
    bool moving = false;
    robot.parent_link(links[first], nullptr, &moving);
    if (moving) break;
  }
  RandomStream random(seed + 1);
  double reach = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::VectorXd q = arm.random_configuration(random);
    const std::vector<Eigen::Isometry3d> poses = arm.link_poses(q);
    reach = std::max(
        reach, (poses.back().translation() - poses[std::min(first, poses.size() - 1)].translation())
                   .norm());
  }
  return reach;
}

}  // namespace

RobotCheck check_robot(const RobotFile& file, const RobotCheckOptions& o) {
  if (o.configurations < 1 || o.configurations > 10000000)
    throw Error("robot check: configurations must be in [1, 10000000]");
  if (o.grid < 1 || o.grid > 50) throw Error("robot check: the grid must be in [1, 50]");
  const RobotModel robot = RobotModel::load(file.urdf_path);
  RobotCheck check;
  check.name = file.name;
  check.arm = robot.chain(robot.root_link(), file.arm_tip);
  check.X_BaseGrasp_home = check.arm.forward(vector_of(file.home_rad));
  check.reach_m = farthest_reach(check.arm, robot, o.seed);
  for (std::size_t i = 0; i < check.arm.dof(); ++i) {
    const JointLimits& limits = check.arm.limits()[i];
    if (!(limits.velocity > 0.0))
      check.problems.push_back(check.arm.joint_names()[i] + " has no velocity limit");
  }
  check_self_collision(check, robot, file, o);
  try {
    check.gripper = match_gripper(file, o.tolerance_m);
  } catch (const Error& e) {
    check.problems.push_back(e.message());  // no two fingers to compare
  }
  for (const GripperMatch& m : check.gripper)
    if (m.required && !m.ok)
      check.problems.push_back(
          "the gripper's " + m.quantity + " is " +
          format("%.4f m in the URDF and %.4f m in the gripper file", m.urdf_m, m.file_m));
  check.reach = reach_grids(file, o);
  for (const ReachGrid& grid : check.reach)
    if (grid.region == "box floor" &&
        10 * grid.points_reachable < 9 * (grid.points - grid.points_hand_blocked))
      check.problems.push_back(format(
          "the arm reaches %.0f%% of the points of the box floor from "
          "above where the hand fits (at least 90%% expected)",
          100.0 * grid.points_reachable / std::max(1, grid.points - grid.points_hand_blocked)));
  return check;
}

}  // namespace antipode::collision
