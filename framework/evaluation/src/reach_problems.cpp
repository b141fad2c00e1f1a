// `antipode bench reach --problems N`: the planner on problems drawn from the planning scenes
// (scenes/planning/*.yaml, MotionBenchMaker's scenes), from the robot's home to a hand pose
// in front of (or above) each problem's target, every solid an obstacle.
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/planning_problems.hpp"
#include "antipode/evaluation/reach_bench.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"
#include "reach_figures.hpp"

namespace antipode::evaluation {
namespace {

// At most this many draws per problem asked for before a scene counts as misplaced.
constexpr int kDrawsPerProblem = 200;

std::shared_ptr<MotionPlanner> planner_of(const bt::Tree& tree, const ReachBenchOptions& o) {
  auto planner = std::dynamic_pointer_cast<MotionPlanner>(tree.component("planner"));
  if (!planner)
    throw Error(o.scene_tree +
                ": bench reach --problems needs a motion planner component "
                "named 'planner'");
  return planner;
}

// X_BaseFrame of a link fixed to the root (a scene's frame; the Panda's panda_link0).
Eigen::Isometry3d fixed_frame(const RobotModel& robot, const std::string& frame,
                              const std::string& scene_path) {
  if (!robot.has_link(frame))
    throw Error(scene_path + ": no link '" + frame + "' in " + robot.source() +
                did_you_mean(frame, robot.link_names()));
  const KinematicChain chain = robot.chain(robot.root_link(), frame);
  if (chain.dof() != 0)
    throw Error(scene_path + ": frame '" + frame + "' moves with a joint; name a link fixed to '" +
                robot.root_link() + "'");
  return chain.forward(Eigen::VectorXd());
}

// The planners of a run: the tree's, and with `side_by_side` its twin with FCL alone, checking
// each segment's states in order (the baseline).
struct Planners {
  std::optional<bt::Tree> tree, exact_tree;
  std::shared_ptr<MotionPlanner> planner, exact;
};

Planners load_planners(Session& session, const ReachBenchOptions& o) {
  TreeRunSettings settings;
  settings.seed = o.seed;
  if (!tree_robot_path(o.scene_tree, {}).empty()) settings.set.push_back("robot=" + o.robot_path);
  settings.set.insert(settings.set.end(), o.set.begin(), o.set.end());
  Planners p;
  p.tree.emplace(load_tree_for(session, o.scene_tree, {}, settings));
  p.planner = planner_of(*p.tree, o);
  if (o.side_by_side) {
    settings.set.push_back("planner.collision=exact");
    settings.set.push_back("planner.segment_order=in_order");
    p.exact_tree.emplace(load_tree_for(session, o.scene_tree, {}, settings));
    p.exact = planner_of(*p.exact_tree, o);
  }
  return p;
}

// One scene's problems.
struct SceneRun {
  std::vector<PlanFigures> plans, exact_plans;
  std::map<std::string, int> set_aside;  // draws without a collision-free goal, by why
  std::uint64_t draws = 0;
};

std::string reasons(const std::map<std::string, int>& set_aside) {
  std::ostringstream out;
  for (const auto& [why, count] : set_aside)
    out << (out.tellp() > 0 ? ", " : "") << why << " " << count;
  return out.str();
}

// As MotionBenchMaker keeps only problems it could solve, draws whose goal has no
// collision-free IK are set aside (counted by why) and the next seed is drawn.
SceneRun run_scene(const PlanningScene& scene, const RobotModel& robot,
                   const std::string& robot_name, const JointState& home, const Planners& p,
                   const ReachBenchOptions& o) {
  const Eigen::Isometry3d X_BaseFrame =
      fixed_frame(robot, planning_frame(scene, robot_name), scene.path);
  SceneRun run;
  while (run.plans.size() < std::size_t(o.problems)) {
    if (run.draws >= std::uint64_t(kDrawsPerProblem) * std::uint64_t(o.problems)) {
      std::ostringstream message;
      message << scene.path << ": " << run.draws << " draws gave only " << run.plans.size()
              << " problems with a collision-free goal (" << reasons(run.set_aside) << ")";
      throw Error(message.str(), {},
                  "check where the scene stands for this robot (its robots: entry)");
    }
    const std::uint64_t seed = o.seed + run.draws++;
    const PlanningQuery query = sample_planning_query(scene, robot_name, X_BaseFrame, seed);
    PlanningProblem problem;
    problem.grasp.frame = robot.root_link();
    problem.grasp.X_FrameHand = query.X_BaseHand;
    problem.start = home;
    problem.standoff_m = 0.0;
    problem.obstacles = query.obstacles;
    problem.seed = seed;
    problem.time_limit_s = 0.0;  // the planner's own (`--set planner.time_limit_s=...`)
    const PlanningResult result = p.planner->plan(problem);
    if (!has_goal(result.status)) {
      // The contact's link names what is in the way; the obstacle varies by draw.
      const std::string detail = result.detail.substr(0, result.detail.rfind(" with "));
      ++run.set_aside[std::string(to_string(result.status)) +
                      (detail.empty() ? "" : " (" + detail + ")")];
      continue;
    }
    run.plans.push_back(figures_of(result));
    if (p.exact) run.exact_plans.push_back(figures_of(p.exact->plan(problem)));
  }
  return run;
}

}  // namespace

nlohmann::ordered_json bench_planning_problems(const ReachBenchOptions& o) {
  const RobotFile robot_file = read_robot_file(o.robot_path);
  const RobotModel robot = RobotModel::load(robot_file.urdf_path);
  const std::string robot_name = std::filesystem::path(o.robot_path).stem().string();
  JointState home;
  home.names = robot.chain(robot.root_link(), robot_file.arm_tip).joint_names();
  home.positions_rad = robot_file.home_rad;
  Session session = open_session();
  const Planners planners = load_planners(session, o);

  nlohmann::ordered_json out = {{"problems_per_scene", o.problems},
                                {"scenes", nlohmann::json::array()}};
  std::vector<PlanFigures> all, all_exact;
  for (const std::string& path : o.problem_scenes) {
    const SceneRun run = run_scene(read_planning_scene(path), robot, robot_name, home, planners, o);
    nlohmann::ordered_json s = {
        {"scene", path}, {"draws", run.draws}, {"set_aside", run.set_aside}};
    s.update(planning_summary(run.plans));
    if (planners.exact) s["exact"] = planning_summary(run.exact_plans);
    std::cout << planning_line(std::filesystem::path(path).stem().string(), s) << "\n";
    if (planners.exact) std::cout << planning_line(kBaselinePlannerLine, s["exact"]) << "\n";
    out["scenes"].push_back(s);
    all.insert(all.end(), run.plans.begin(), run.plans.end());
    all_exact.insert(all_exact.end(), run.exact_plans.begin(), run.exact_plans.end());
  }
  out["all"] = planning_summary(all);
  std::cout << planning_line("all planning scenes", out["all"]) << "\n";
  if (planners.exact) {
    out["all"]["exact"] = planning_summary(all_exact);
    std::cout << planning_line(kBaselinePlannerLine, out["all"]["exact"]) << "\n";
  }
  return out;
}

}  // namespace antipode::evaluation
