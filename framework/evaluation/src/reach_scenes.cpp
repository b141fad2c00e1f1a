// `antipode bench reach --scenes N`: motion planning from the arm's home to the grasps
// selected in seeded clutter scenes, through the plugin components a pick tree declares.
#include <chrono>
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

// A selection's times per scene: the whole selection and its reach checks (ms).
struct SelectionMs {
  std::vector<double> whole, reach;
};

// `selector`'s selection from `hands`, its times appended to `ms`.
HandSet timed_selection(const GraspSelector& selector, const HandSet& hands,
                        SelectionContext context, SelectionMs& ms) {
  SelectionTimes times;
  context.times = &times;
  const auto t0 = std::chrono::steady_clock::now();
  HandSet selection = selector.select(hands, context);
  ms.whole.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  ms.reach.push_back(1e3 * times.reach_s);
  return selection;
}

// Whether two selections chose the same grasps in the same order.
bool same_grasps(const HandSet& a, const HandSet& b) {
  const auto grasps = [](const HandSet& s) {
    std::vector<Eigen::Matrix4d> poses;
    for (const Hand& h : s.hands) {
      if (h.rejection != Rejection::kNone) break;
      poses.push_back(h.X_FrameHand.matrix());
    }
    return poses;
  };
  return grasps(a) == grasps(b);
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
  // Side by side, the baseline: the same problems with FCL alone, each segment's states checked
  // in order, and the selector with the slower ways it keeps for comparison - FCL alone, every
  // IK solution of a grasp solved before any is checked, orocos-kdl's kinematics, the points'
  // octree built point by point.
  std::optional<bt::Tree> exact_tree;
  std::shared_ptr<MotionPlanner> exact;
  std::shared_ptr<GraspSelector> exact_selector;
  if (o.side_by_side) {
    for (const char* entry :
         {"planner.collision=exact", "planner.segment_order=in_order", "selector.collision=exact",
          "selector.reach_search=exhaustive", "selector.ik_kinematics=kdl",
          "selector.points_octree=point_by_point"})
      settings.set.push_back(entry);
    exact_tree.emplace(load_tree_for(session, o.scene_tree, {}, settings));
    exact = component_of<MotionPlanner>(*exact_tree, "planner", o);
    exact_selector = component_of<GraspSelector>(*exact_tree, "selector", o);
  }

  std::vector<PlanFigures> plans, exact_plans;
  SelectionMs select_ms, exact_select_ms;
  int scenes_with_grasps = 0, same_selections = 0;
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
    const HandSet selection = timed_selection(*selector, hands, context, select_ms);
    if (exact_selector) {
      const HandSet baseline = timed_selection(*exact_selector, hands, context, exact_select_ms);
      same_selections += same_grasps(selection, baseline) ? 1 : 0;
    }
    bool any = false;
    for (const Hand& grasp : selection.hands) {
      if (grasp.rejection != Rejection::kNone) break;  // the grasps come first
      any = true;
      PlanningProblem problem;
      problem.grasp = grasp;
      problem.start = cell->arm_state();
      problem.scene = cloud;
      problem.seed = seed;
      problem.time_limit_s = 0.0;  // the planner's own (`--set planner.time_limit_s=...`)
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
  out.update(selection_summary(select_ms.whole, select_ms.reach));
  const int with_goal = out["with_ik"], solved = out["successes"];
  if (exact) {
    out["exact"] = planning_summary(exact_plans);
    out["exact"].update(selection_summary(exact_select_ms.whole, exact_select_ms.reach));
    out["same_selections"] = same_selections;
  }
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
  std::cout << selection_line("  selection", out) << "\n";
  if (exact) {
    std::cout << planning_line(kBaselinePlannerLine, out["exact"]) << "\n"
              << selection_line(
                     "  the baseline selection (FCL alone, every IK solution first, "
                     "orocos-kdl's kinematics, the octree point by point)",
                     out["exact"])
              << "; the same grasps in " << same_selections << " of " << select_ms.whole.size()
              << " scenes\n";
  }
  return out;
}

}  // namespace antipode::evaluation
