// `antipode bench reach --scenes N`: motion planning from the arm's home to the grasps
// selected in seeded clutter scenes, through the plugin components a pick tree declares.
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/evaluation/reach_bench.hpp"
#include "antipode/evaluation/session.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "reach_figures.hpp"

namespace antipode::evaluation {
namespace {

template <typename C>
std::shared_ptr<C> component_of(const bt::Tree& tree, const std::string& name,
                                const ReachBenchOptions& o) {
  auto component = std::dynamic_pointer_cast<C>(tree.component(name));
  if (!component) {
    throw Error(o.scene_tree +
                ": bench reach --scenes needs the components cell, sampler, "
                "classifier, selector and planner; '" +
                name + "' is missing or of another kind");
  }
  return component;
}

}  // namespace

nlohmann::ordered_json bench_planning_scenes(const ReachBenchOptions& o) {
  Session session = open_session();
  TreeRunSettings settings;
  settings.seed = o.seed;
  settings.set = {"cell.scene=" + o.scene_file};
  // A tree with a `robot` setting (trees/plan_reach.yaml) plans with the bench's robot; one
  // without plans with the robots it names.
  if (!tree_robot_path(o.scene_tree, {}).empty()) settings.set.push_back("robot=" + o.robot_path);
  settings.set.insert(settings.set.end(), o.set.begin(), o.set.end());
  const bt::Tree tree = load_tree_for(session, o.scene_tree, {}, settings);
  const auto cell = component_of<Cell>(tree, "cell", o);
  const auto sampler = component_of<Sampler>(tree, "sampler", o);
  const auto classifier = component_of<Classifier>(tree, "classifier", o);
  const auto selector = component_of<GraspSelector>(tree, "selector", o);
  const auto planner = component_of<MotionPlanner>(tree, "planner", o);
  // Side by side: the same problems with FCL alone.
  std::optional<bt::Tree> exact_tree;
  std::shared_ptr<MotionPlanner> exact;
  if (o.side_by_side) {
    settings.set.push_back("planner.collision=exact");
    exact_tree.emplace(load_tree_for(session, o.scene_tree, {}, settings));
    exact = component_of<MotionPlanner>(*exact_tree, "planner", o);
  }

  std::vector<PlanFigures> plans, exact_plans;
  int scenes_with_grasps = 0;
  for (int s = 0; s < o.scenes; ++s) {
    const std::uint64_t seed = o.seed + std::uint64_t(s);
    cell->reset(seed);
    const auto cloud = std::make_shared<const Cloud>(cell->capture(o.views));
    HandSet hands;
    try {
      hands = sampler->sample(*cloud, RandomStream(seed), {});
    } catch (const Error&) {
      continue;  // nothing to grasp in the workspace
    }
    classifier->classify(hands, {});
    SelectionContext context;
    context.scene = cloud;  // the whole capture: the arm passes outside the workspace
    context.start = cell->arm_state();
    const HandSet selection = selector->select(hands, context);
    bool any = false;
    for (const Hand& grasp : selection.hands) {
      if (grasp.rejection != Rejection::kNone) break;  // the grasps come first
      any = true;
      PlanningProblem problem;
      problem.grasp = grasp;
      problem.start = cell->arm_state();
      problem.scene = cloud;
      problem.seed = seed;
      plans.push_back(figures_of(planner->plan(problem)));
      if (exact) exact_plans.push_back(figures_of(exact->plan(problem)));
    }
    scenes_with_grasps += any ? 1 : 0;
    std::cerr << "\rscene " << s + 1 << "/" << o.scenes << ", " << plans.size() << " grasps"
              << std::flush;
  }
  std::cerr << "\n";

  nlohmann::ordered_json out = {{"scenes", o.scenes},
                                {"scene_file", o.scene_file},
                                {"scenes_with_grasps", scenes_with_grasps}};
  out.update(planning_summary(plans));
  const int with_goal = out["with_ik"], solved = out["successes"];
  if (exact) out["exact"] = planning_summary(exact_plans);
  const auto pct = [](int n, int d) { return d ? 100.0 * n / d : 0.0; };
  std::cout << std::fixed << std::setprecision(2) << "planning, " << o.scenes << " scenes of "
            << o.scene_file << ": " << plans.size() << " selected grasps, " << with_goal
            << " with collision-free IK and approach (" << pct(with_goal, int(plans.size()))
            << "%), " << solved << " planned (" << pct(solved, with_goal) << "% of those)\n"
            << "  search median " << out["median_ms"].get<double>() << " ms, p90 "
            << out["p90_ms"].get<double>() << " ms; IK and approach median "
            << out["goal_median_ms"].get<double>() << " ms; shortcutting median "
            << out["simplify_median_ms"].get<double>() << " ms; " << std::setprecision(0)
            << out["collision_checks_per_s"].get<double>()
            << " arm states checked per second of search\n";
  if (exact) std::cout << planning_line("  the same with FCL alone", out["exact"]) << "\n";
  return out;
}

}  // namespace antipode::evaluation
