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

  // Planning problems drawn from planning scenes (planning_problems.hpp): `problems` per scene
  // file (seeds `seed`, `seed` + 1, ...), planned by the scene tree's planner; 0 skips it.
  int problems = 0;
  std::vector<std::string> problem_scenes{
      "scenes/planning/mbm_table_pick.yaml",     "scenes/planning/mbm_box.yaml",
      "scenes/planning/mbm_cage.yaml",           "scenes/planning/mbm_bookshelf_tall.yaml",
      "scenes/planning/mbm_bookshelf_thin.yaml", "scenes/planning/mbm_bookshelf_small.yaml"};
  /// Plan every problem (clutter scenes and planning scenes) twice: with the planner as the
  /// tree sets it and with `collision: exact` (FCL alone) and `segment_order: in_order`,
  /// reported side by side.
  bool side_by_side = false;
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

/// The planning-scene part: `problems` problems per file of `problem_scenes`, each from the
/// robot file's home to the query's hand pose, planned by the scene tree's planner (and its
/// FCL-only twin with `side_by_side`). Prints the figures per scene and in all, and returns
/// them as the report's "problems" object. Throws antipode::Error for a bad scene file or one
/// that does not place the robot.
nlohmann::ordered_json bench_planning_problems(const ReachBenchOptions& options);

}  // namespace antipode::evaluation
