// Reach over the cell's table and box: the algorithm.
//  1. The table (a slab whose top is `top_z_m`) and the box's four walls, from the scene
//     file, are the obstacles; the robot's own links the rest.
//  2. Grid points over the box floor (`grid` per side, 3 cm in from the walls) and over the
//     table around the box (twice as many per side, outside the box), each a top-down grasp
//     whose fingertips stop 5 mm above the surface, closing along four directions 45 degrees
//     apart.
//  3. A point is reachable when some closing direction is (a hand wider than it is thick fits
//     near a wall only along it). Each grasp is checked as the selector checks it (check_reach:
//     collision-free IK at the grasp and at the pre-grasp 10 cm back, from home), the hand half
//     turned too.
#include <algorithm>
#include <cmath>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "collision_pairs.hpp"
#include "reach_check.hpp"
#include "robot_check.hpp"

namespace antipode::collision {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The table and the box as the cell reads them (plugins/cells/bullet_cell/scene_spec.hpp:
// the same defaults, the box centred on the table unless it says otherwise).
struct Layout {
  double top_z = -0.295;
  Eigen::Vector2d table_centre{0.725, -0.135}, table_size{0.9, 1.0};
  bool has_box = false;
  Eigen::Vector2d box_centre{0.725, -0.135}, box_inner{0.3, 0.3};
  double wall_height = 0.06, wall_thickness = 0.01;
};

void read_pair(const YAML::Node& map, const char* key, Eigen::Vector2d& value) {
  const YAML::Node node = map[key];
  if (!node.IsDefined()) return;
  if (!node.IsSequence() || node.size() != 2)
    throw Error(std::string("'") + key + "' must be [x, y]");
  value = {node[0].as<double>(), node[1].as<double>()};
}

void read_number(const YAML::Node& map, const char* key, double& value) {
  if (map[key].IsDefined()) value = map[key].as<double>();
}

Layout read_layout(const std::string& path) {
  Layout layout;
  try {
    const YAML::Node scene = YAML::LoadFile(path);
    if (!scene.IsMap()) throw Error("not a map of scene keys");
    const YAML::Node table = scene["table"];
    if (table.IsDefined() && table.IsMap()) {
      read_number(table, "top_z_m", layout.top_z);
      read_pair(table, "center_m", layout.table_centre);
      read_pair(table, "size_m", layout.table_size);
    }
    layout.box_centre = layout.table_centre;
    const YAML::Node box = scene["box"];
    if (box.IsDefined() && box.IsMap()) {
      layout.has_box = true;
      read_pair(box, "center_m", layout.box_centre);
      read_pair(box, "inner_size_m", layout.box_inner);
      read_number(box, "wall_height_m", layout.wall_height);
      read_number(box, "wall_thickness_m", layout.wall_thickness);
    }
  } catch (const YAML::Exception& e) {
    throw Error("scene file '" + path + "': " + e.what());
  } catch (const Error& e) {
    throw Error("scene file '" + path + "': " + e.message());
  }
  return layout;
}

void add_obstacles(ArmCollisionWorld& world, const Layout& l) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() << l.table_centre.x(), l.table_centre.y(), l.top_z - 0.025;
  world.add_box("table", X, Eigen::Vector3d(l.table_size.x(), l.table_size.y(), 0.05));
  if (!l.has_box) return;
  const Eigen::Vector2d half = l.box_inner / 2 + Eigen::Vector2d::Constant(l.wall_thickness / 2);
  const double z = l.top_z + l.wall_height / 2;
  const double outer_x = l.box_inner.x() + 2 * l.wall_thickness;
  for (double side : {-1.0, 1.0}) {
    X.translation() << l.box_centre.x() + side * half.x(), l.box_centre.y(), z;
    world.add_box(side < 0 ? "near_wall" : "far_wall", X,
                  Eigen::Vector3d(l.wall_thickness, l.box_inner.y(), l.wall_height));
    X.translation() << l.box_centre.x(), l.box_centre.y() + side * half.y(), z;
    world.add_box(side < 0 ? "right_wall" : "left_wall", X,
                  Eigen::Vector3d(outer_x, l.wall_thickness, l.wall_height));
  }
}

bool in_box(const Layout& l, const Eigen::Vector2d& p, double margin_m) {
  return l.has_box && ((p - l.box_centre).cwiseAbs().array() <=
                       (l.box_inner / 2).array() + l.wall_thickness + margin_m)
                          .all();
}

// A top-down grasp at `p`, its palm `height_m` above the table, closing along `yaw`.
Eigen::Isometry3d top_down(const Eigen::Vector2d& p, double z, double yaw) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear().col(0) = -Eigen::Vector3d::UnitZ();                         // approach: down
  X.linear().col(1) = Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0);  // closing
  X.linear().col(2) = X.linear().col(0).cross(X.linear().col(1));
  X.translation() << p.x(), p.y(), z;
  return X;
}

// How a grasp ended: reachable, blocked by the hand alone (its links touch the scene), or
// out of the arm's reach.
enum class Outcome { kReachable, kHandBlocked, kArm };

struct Arm {
  const KinematicChain& chain;
  const ArmCollisionWorld& world;
  const std::vector<std::string>& hand_links;
  Eigen::VectorXd home;
};

// Whether only the hand keeps the arm from the grasp: the hand alone touches the scene (not
// itself or the arm: that is self-collision) where the arm has joint values that put it
// (check_reach reports the hand's contact before solving any IK).
bool hand_contact(const Reach& reach, const std::vector<std::string>& hand_links, const Arm& arm,
                  const Eigen::Isometry3d& X) {
  if (reach.status != ReachStatus::kInCollisionAtGrasp) return false;
  if (reach.detail.rfind("collision: ", 0) != 0) return false;
  const bool hand = std::any_of(hand_links.begin(), hand_links.end(), [&](const std::string& l) {
    return reach.detail.find(": " + l + " with ") != std::string::npos;
  });
  return hand && solve_ik(arm.chain, X, arm.home).status == IkStatus::kSolved;
}

Outcome try_grasp(ReachGrid& grid, const Arm& arm, const Eigen::Isometry3d& X) {
  ++grid.grasps;
  ReachOptions options;  // whether, not how: as the selector
  options.search = ReachSearch::kFirstFree;
  Reach reach = check_reach(arm.chain, arm.world, X, arm.home, options);
  bool hand_only = hand_contact(reach, arm.hand_links, arm, X);
  if (reach.status != ReachStatus::kReachable) {
    const Reach other = check_reach(arm.chain, arm.world, half_turned(X), arm.home, options);
    if (other.status == ReachStatus::kReachable) reach = other;
    hand_only = hand_only && hand_contact(other, arm.hand_links, arm, half_turned(X));
  }
  if (reach.status == ReachStatus::kReachable) {
    ++grid.reachable;
    return Outcome::kReachable;
  }
  ++grid.failures[to_string(reach.status)];
  return hand_only ? Outcome::kHandBlocked : Outcome::kArm;
}

// The four closing directions at `p`: whether any is reachable.
// The four closing directions at `p`: reachable when any is, hand-blocked when every one
// failed only because the hand touched the scene.
void try_point(ReachGrid& grid, const Arm& arm, const Eigen::Vector2d& p, double palm_z) {
  bool any = false, hand_only = true;
  for (int k = 0; k < 4; ++k) {
    const Outcome outcome = try_grasp(grid, arm, top_down(p, palm_z, k * kPi / 4));
    any = any || outcome == Outcome::kReachable;
    hand_only = hand_only && outcome == Outcome::kHandBlocked;
  }
  ++grid.points;
  if (any) ++grid.points_reachable;
  if (!any && hand_only) ++grid.points_hand_blocked;
}

}  // namespace

std::vector<ReachGrid> reach_grids(const RobotFile& robot_file, const RobotCheckOptions& o) {
  if (o.scene_path.empty()) return {};
  const Layout layout = read_layout(o.scene_path);
  const RobotModel robot = RobotModel::load(robot_file.urdf_path);
  const KinematicChain arm = robot.chain(robot.root_link(), robot_file.arm_tip);
  ArmCollisionWorld world(robot, arm);
  add_obstacles(world, layout);
  Eigen::VectorXd home(arm.dof());
  for (std::size_t i = 0; i < arm.dof(); ++i) home[Eigen::Index(i)] = robot_file.home_rad[i];
  // The palm stands so that the fingertips stop 5 mm above the surface: the URDF's fingers,
  // or the gripper file's depth where they are shorter.
  double reach_m = robot_file.gripper.depth_m;
  try {
    for (const GripperMatch& m : match_gripper(robot_file, o.tolerance_m))
      if (m.quantity.rfind("finger reach", 0) == 0) reach_m = std::max(reach_m, m.urdf_m);
  } catch (const Error&) {
    // no two fingers: the gripper file's depth (check_robot reports the fingers)
  }
  const double palm_z = layout.top_z + 0.005 + reach_m;
  const std::vector<std::string> hand_links = shaped_links_below(robot, robot_file.gripper_from);
  const Arm on_arm{arm, world, hand_links, home};
  std::vector<ReachGrid> grids;
  if (layout.has_box) {
    ReachGrid box{"box floor", 0, 0, 0, 0, 0, {}};
    const Eigen::Vector2d span = layout.box_inner - Eigen::Vector2d::Constant(0.06);
    for (int i = 0; i < o.grid; ++i)
      for (int j = 0; j < o.grid; ++j) {
        const Eigen::Vector2d f((i + 0.5) / o.grid - 0.5, (j + 0.5) / o.grid - 0.5);
        const Eigen::Vector2d p = layout.box_centre + span.cwiseProduct(f);
        try_point(box, on_arm, p, palm_z);
      }
    grids.push_back(box);
  }
  ReachGrid table{"table around the box", 0, 0, 0, 0, 0, {}};
  const int n = 2 * o.grid;
  const Eigen::Vector2d span = layout.table_size - Eigen::Vector2d::Constant(0.06);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d f((i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5);
      const Eigen::Vector2d p = layout.table_centre + span.cwiseProduct(f);
      if (in_box(layout, p, 0.05)) continue;  // fingers would stand on a wall
      try_point(table, on_arm, p, palm_z);
    }
  grids.push_back(table);
  return grids;
}

}  // namespace antipode::collision
