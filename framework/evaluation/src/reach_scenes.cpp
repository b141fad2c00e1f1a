// `antipode bench reach --scenes N`: motion planning from the arm's home to the grasps
// selected in seeded clutter scenes, through the plugin components a pick tree declares.
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>

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

// The figures of one planning call.
struct PlanFigures {
  PlanningStatus status;
  double goal_ms, search_ms, simplify_ms;
  long checks;
};

bool has_goal(PlanningStatus s) {
  return s == PlanningStatus::kSolved || s == PlanningStatus::kTimedOut ||
         s == PlanningStatus::kCancelled;
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

  std::vector<PlanFigures> plans;
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
      const PlanningResult r = planner->plan(problem);
      plans.push_back(
          {r.status, 1e3 * r.goal_s, 1e3 * r.search_s, 1e3 * r.simplify_s, r.collision_checks});
    }
    scenes_with_grasps += any ? 1 : 0;
    std::cerr << "\rscene " << s + 1 << "/" << o.scenes << ", " << plans.size() << " grasps"
              << std::flush;
  }
  std::cerr << "\n";

  std::map<std::string, int> statuses;
  std::vector<double> goal_ms, search_ms, simplify_ms;
  int with_goal = 0, solved = 0;
  double checks = 0.0, search_total_s = 0.0;
  for (const PlanFigures& p : plans) {
    ++statuses[to_string(p.status)];
    goal_ms.push_back(p.goal_ms);
    if (!has_goal(p.status)) continue;
    ++with_goal;
    checks += double(p.checks);
    search_total_s += p.search_ms / 1e3;
    search_ms.push_back(p.search_ms);
    if (p.status != PlanningStatus::kSolved) continue;
    ++solved;
    simplify_ms.push_back(p.simplify_ms);
  }
  nlohmann::ordered_json out = {
      {"scenes", o.scenes},
      {"scene_file", o.scene_file},
      {"scenes_with_grasps", scenes_with_grasps},
      {"attempts", int(plans.size())},
      {"with_ik", with_goal},
      {"successes", solved},
      {"median_ms", percentile(search_ms, 0.5)},
      {"p90_ms", percentile(search_ms, 0.9)},
      {"goal_median_ms", percentile(goal_ms, 0.5)},
      {"goal_p90_ms", percentile(goal_ms, 0.9)},
      {"simplify_median_ms", percentile(simplify_ms, 0.5)},
      {"collision_checks_per_s", search_total_s > 0.0 ? checks / search_total_s : 0.0},
      {"statuses", statuses}};
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
  return out;
}

}  // namespace antipode::evaluation
