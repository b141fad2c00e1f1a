#pragma once
// The figures of planning calls, summed up for `antipode bench reach`'s reports: the clutter
// scenes (reach_scenes.cpp) and the planning scenes' problems (reach_problems.cpp).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antipode/interfaces/motion_planner.hpp"

namespace antipode::evaluation {

/// The figures of one planning call.
struct PlanFigures {
  PlanningStatus status;
  double goal_ms, search_ms, simplify_ms;
  long checks;
};

PlanFigures figures_of(const PlanningResult& r);

/// Whether a call got as far as the search (a goal was found).
bool has_goal(PlanningStatus s);

/// Attempts, those with a goal, successes, search median / 90th / 99th percentile, goal and
/// shortcutting medians, states checked per second of search, the most states one search
/// checked (`most_states`), and the statuses.
nlohmann::ordered_json planning_summary(const std::vector<PlanFigures>& plans);

/// The label of the side-by-side baseline planner's line (`--side-by-side`: FCL alone, each
/// motion's states in order).
inline constexpr const char* kBaselinePlannerLine = "  the same with FCL alone, segments in order";

/// One line of those figures for standard output, after `label`.
std::string planning_line(const std::string& label, const nlohmann::ordered_json& summary);

/// The median and 90th percentile of the selections' times (`select_ms`, one per scene) and
/// of their reach checks' (`reach_ms`, SelectionTimes::reach_s in ms), as
/// `selection_median_ms`, `selection_p90_ms`, `reach_check_median_ms` and
/// `reach_check_p90_ms`.
nlohmann::ordered_json selection_summary(const std::vector<double>& select_ms,
                                         const std::vector<double>& reach_ms);

/// "LABEL per scene: median M ms, p90 P ms; its reach checks: median R ms, p90 Q ms" from a
/// summary holding selection_summary's figures.
std::string selection_line(const std::string& label, const nlohmann::ordered_json& summary);

}  // namespace antipode::evaluation
