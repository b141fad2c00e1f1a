#include "reach_figures.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>

#include "antipode/evaluation/bench_report.hpp"

namespace antipode::evaluation {

bool has_goal(PlanningStatus s) {
  return s == PlanningStatus::kSolved || s == PlanningStatus::kTimedOut ||
         s == PlanningStatus::kCancelled;
}

PlanFigures figures_of(const PlanningResult& r) {
  return {r.status, 1e3 * r.goal_s, 1e3 * r.search_s, 1e3 * r.simplify_s, r.collision_checks};
}

nlohmann::ordered_json planning_summary(const std::vector<PlanFigures>& plans) {
  std::map<std::string, int> statuses;
  std::vector<double> goal_ms, search_ms, simplify_ms;
  int with_goal = 0, solved = 0;
  double checks = 0.0, search_total_s = 0.0;
  long most_states = 0;
  for (const PlanFigures& p : plans) {
    ++statuses[to_string(p.status)];
    goal_ms.push_back(p.goal_ms);
    if (!has_goal(p.status)) continue;
    ++with_goal;
    checks += double(p.checks);
    most_states = std::max(most_states, p.checks);
    search_total_s += p.search_ms / 1e3;
    search_ms.push_back(p.search_ms);
    if (p.status != PlanningStatus::kSolved) continue;
    ++solved;
    simplify_ms.push_back(p.simplify_ms);
  }
  return {{"attempts", int(plans.size())},
          {"with_ik", with_goal},
          {"successes", solved},
          {"median_ms", percentile(search_ms, 0.5)},
          {"p90_ms", percentile(search_ms, 0.9)},
          {"p99_ms", percentile(search_ms, 0.99)},
          {"goal_median_ms", percentile(goal_ms, 0.5)},
          {"goal_p90_ms", percentile(goal_ms, 0.9)},
          {"simplify_median_ms", percentile(simplify_ms, 0.5)},
          {"collision_checks_per_s", search_total_s > 0.0 ? checks / search_total_s : 0.0},
          {"most_states", most_states},
          {"statuses", statuses}};
}

std::string planning_line(const std::string& label, const nlohmann::ordered_json& s) {
  const auto pct = [](int n, int d) { return d ? 100.0 * n / d : 0.0; };
  const int attempts = s["attempts"], with_ik = s["with_ik"], solved = s["successes"];
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << label << ": " << attempts << " problems";
  if (with_ik != attempts)
    out << ", " << with_ik << " with a collision-free goal (" << pct(with_ik, attempts) << "%)";
  out << ", " << solved << " planned (" << pct(solved, with_ik) << "%); search median "
      << s["median_ms"].get<double>() << " ms, p90 " << s["p90_ms"].get<double>() << " ms, p99 "
      << s["p99_ms"].get<double>() << " ms; " << std::setprecision(0)
      << s["collision_checks_per_s"].get<double>() << " states checked per second of search";
  return out.str();
}

nlohmann::ordered_json selection_summary(const std::vector<double>& select_ms,
                                         const std::vector<double>& reach_ms) {
  return {{"selection_median_ms", percentile(select_ms, 0.5)},
          {"selection_p90_ms", percentile(select_ms, 0.9)},
          {"reach_check_median_ms", percentile(reach_ms, 0.5)},
          {"reach_check_p90_ms", percentile(reach_ms, 0.9)}};
}

std::string selection_line(const std::string& label, const nlohmann::ordered_json& s) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << label << " per scene: median "
      << s["selection_median_ms"].get<double>() << " ms, p90 "
      << s["selection_p90_ms"].get<double>() << " ms; its reach checks: median "
      << s["reach_check_median_ms"].get<double>() << " ms, p90 "
      << s["reach_check_p90_ms"].get<double>() << " ms";
  return out.str();
}

}  // namespace antipode::evaluation
