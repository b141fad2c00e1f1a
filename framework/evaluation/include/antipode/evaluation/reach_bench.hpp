#pragma once
// `antipode bench reach`: inverse kinematics of a robot arm measured with TRAC-IK's
// protocol, and motion planning to the grasps selected in seeded clutter scenes
// (docs/cli.md, docs/results.md).

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

struct ReachBenchOptions {
  std::string robot_path = "robots/baxter/baxter.yaml";  ///< a robot file
  std::string base_link;   ///< the IK chain's base; "" = the URDF's root
  std::string tip_link;    ///< its tip; "" = the robot file's gripper_from (the flange or hand)
  int ik_poses = 10000;    ///< random reachable poses
  std::uint64_t seed = 1;  ///< the poses' random stream
  std::vector<std::string> solvers{"dls", "kdl"};
  double timeout_ms = 5.0;  ///< per pose
  double tolerance = 1e-5;  ///< m and rad per component
  std::string report_path;  ///< JSON report ("" = none)

  // Planning in clutter: the components of `scene_tree` (cell, sampler, classifier, selector,
  // planner), the cell's scene swapped for `scene_file` and its `robot` setting for
  // `robot_path`; 0 scenes skips it.
  int scenes = 0;
  std::string scene_tree = "trees/plan_reach.yaml";
  std::string scene_file = "scenes/pile_procedural.yaml";
  std::vector<std::string> views{"left", "right"};  ///< the cell's views to capture
  std::vector<std::string> set;  ///< "component.key=value" overrides for the scene tree
};

/// Draws `ik_poses` joint vectors uniformly within the limits, takes their forward
/// kinematics as targets and solves each from the mid-range seed with every solver; then,
/// with `scenes` > 0, plans from the arm's home to every grasp selected in each scene
/// (bench_planning_scenes); prints success rates and times on standard output and returns
/// the report ("ik", "ik_NAME" for the other solvers, "planning"), which the caller writes to
/// `report_path`. Throws antipode::Error for bad options (the report path included).
nlohmann::ordered_json run_reach_bench(const ReachBenchOptions& options);

/// The planning part: for scenes seeded `seed`, `seed` + 1, ..., the scene tree's cell is
/// reset, captured from all its views, sampled, classified and selected, and the planner
/// plans for every selected grasp from the cell's arm state. Prints the figures and returns
/// them as the report's "planning" object. Throws antipode::Error for a tree without the
/// five components.
nlohmann::ordered_json bench_planning_scenes(const ReachBenchOptions& options);

}  // namespace antipode::evaluation
