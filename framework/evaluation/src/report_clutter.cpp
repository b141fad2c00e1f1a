// The report's section for a clutter bench (antipode bench clutter): settings and command,
// grasp success and objects removed beside the paper's, what was left and whether the gripper
// could hold it, failures in the paper's groups, how the runs ended, each run's line and
// objects left, seconds; a chart of each run.
#include <cstdio>
#include <filesystem>

#include "antipode/evaluation/bar_chart.hpp"
#include "antipode/evaluation/bench_objects.hpp"
#include "antipode/evaluation/clutter_bench.hpp"
#include "antipode/evaluation/clutter_protocols.hpp"
#include "antipode/evaluation/report_sections.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

std::string settings_text(const Json& r) {
  const int runs = r.at("runs"), first = r.at("seed");
  return std::to_string(runs) + " runs of " + r.at("objects_per_run").dump() + " objects (" +
         object_set_name(r.at("objects")) + "), seeds " + std::to_string(first) + "-" +
         std::to_string(first + runs - 1) + ", tree `" + r.at("tree").get<std::string>() + "`, " +
         noise_phrase(r) + "; " + machine_phrase(r) + ", " + r.at("jobs").dump() +
         " process(es), " + wall_time(r.at("wall_s")) + " of wall time.\n\n";
}

const ClutterProtocol& protocol_of(const Json& r) { return report_protocol(r); }

std::string command_text(const Json& r, const std::string& name) {
  const ClutterProtocol& protocol = protocol_of(r);
  std::string c = "antipode bench clutter";
  if (protocol.name != "paper") c += " --protocol " + protocol.name;
  c += " --objects " + shell_word(r.at("objects")) + " --runs " + r.at("runs").dump();
  if (r.at("objects_per_run") != protocol.objects_per_run)
    c += " --objects-per-run " + r.at("objects_per_run").dump();
  c += " --seed " + r.at("seed").dump();
  if (r.at("tree") != protocol.tree) c += " --tree " + shell_word(r.at("tree"));
  if (r.at("noise") != "tree") c += " --noise " + shell_word(r.at("noise"));
  if (r.contains("gripper")) c += " --gripper " + shell_word(r.at("gripper").at("file"));
  return "```sh\n" + c + set_options(r) + " --jobs " + r.at("jobs").dump() + " --report " + name +
         ".json\n```\n\n";
}

std::string headline(const Json& r, const Json& s) {
  const ClutterProtocol& protocol = protocol_of(r);
  const auto pct = [](double v) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f%%", v);
    return v < 0 ? std::string("-") : std::string(text);
  };
  std::vector<std::vector<std::string>> rows = {
      {"antipode (simulated cell)", rate_with_interval(s.at("successes"), s.at("attempts")),
       rate_with_interval(s.at("removed"), s.at("objects"))}};
  for (const auto& p : protocol.published)
    rows.push_back({p.who, pct(p.success_pct), pct(p.removed_pct)});
  return markdown_table({"", protocol.success_name + " (successes / attempts)",
                         protocol.removed_name + " (removed / objects at the start)"},
                        rows);
}

// The headline's rates again, with the intervals that resample whole runs (`s`, the summary
// of the run records, carries them). Nothing for fewer than two runs.
std::string between_runs(const Json& r, const Json& s) {
  if (!s.at("success_rate").contains("ci95_runs")) return "";
  const ClutterProtocol& protocol = protocol_of(r);
  const auto interval = [](const Json& bounds) {
    char text[32];
    std::snprintf(text, sizeof text, "[%.1f, %.1f]", 100 * bounds.at(0).get<double>(),
                  100 * bounds.at(1).get<double>());
    return std::string(text);
  };
  const int runs = s.at("runs").get<int>() - s.at("errors").get<int>();
  std::string text = "Between runs (the " + std::to_string(runs) +
                     " runs resampled whole, 2,000 bootstrap draws; attempts within a run are "
                     "not independent trials), the 95% intervals are " +
                     interval(s.at("success_rate").at("ci95_runs")) + " for " +
                     protocol.success_name;
  if (s.at("removed_rate").contains("ci95_runs"))
    text +=
        " and " + interval(s.at("removed_rate").at("ci95_runs")) + " for " + protocol.removed_name;
  return text + ".\n\n";
}

// What the objects left say about the removal rate (runs whose cell has ground truth).
std::string what_was_left(const Json& s) {
  if (!s.contains("left_graspable")) return "";
  const int removed = s.at("removed"), left = s.at("left"), left_graspable = s.at("left_graspable");
  const auto [min_m, max_m] = summary_graspable_width_m(s);
  char text[600];
  std::snprintf(text, sizeof text,
                "Of the %d objects left in the box, %d lay too wide or too thin for the gripper "
                "across every horizontal direction (their narrowest horizontal extent outside "
                "%.0f-%.0f cm, the gripper's apertures rounded inwards; some still had a part it "
                "could hold, such as a mug's handle). Removed of the objects it could hold: ",
                left, left - left_graspable, 100 * min_m, 100 * max_m);
  return text + rate_with_interval(removed, removed + left_graspable) + ".\n\n";
}

// "004_sugar_box 9.4 cm, 025_mug 8.1 cm": a run's objects left with their narrowest widths.
std::string left_objects(const Json& run) {
  std::string text;
  for (const Json& object : run.at("left_objects")) {
    char width[32];
    std::snprintf(width, sizeof width, " %.1f cm",
                  100 * object.at("narrowest_horizontal_m").get<double>());
    text += (text.empty() ? "" : ", ") + object.at("name").get<std::string>() + width;
  }
  return text.empty() ? "-" : text;
}

// "slipped 3, closed on nothing 2": a map of counts as a list ("" when empty).
std::string counts_text(const Json& counts) {
  std::string text;
  for (const auto& [what, count] : counts.items())
    text += (text.empty() ? "" : ", ") + what + " " + count.dump();
  return text;
}

std::string failures(const Json& s) {
  const int attempts = s.at("attempts");
  std::vector<std::vector<std::string>> rows;
  for (const auto& [group, count] : s.at("paper_classes").items()) {
    char share[32];
    std::snprintf(share, sizeof share, "%.1f%%",
                  attempts ? 100.0 * count.get<int>() / attempts : 0);
    rows.push_back({group, count.dump(), share});
  }
  const std::string classes = counts_text(s.at("reasons"));
  const std::string stops = counts_text(s.at("stops"));
  char seconds[320];
  std::snprintf(seconds, sizeof seconds,
                "Median cycle (capture to outcome) %.2f s, median run %.1f s; %d of %d cycles "
                "found no grasp; objects out of the workspace (off the table or out of the box) "
                "other than by a pick: %d during the runs",
                s.at("cycle_s_median").get<double>(), s.at("run_s_median").get<double>(),
                s.at("no_grasp").get<int>(), s.at("cycles").get<int>(), s.at("lost").get<int>());
  std::string lost = seconds;
  if (s.contains("missed_at_filling"))  // reports older than the count have no such entry
    lost += ", " + s.at("missed_at_filling").dump() + " while filling the box";
  const std::string groups = rows.empty()
                                 ? "Failures as the paper groups them: none.\n"
                                 : "Failures as the paper groups them (share of attempts):\n\n" +
                                       markdown_table({"group", "attempts", "share"}, rows);
  return groups + "\nFailure classes: " + (classes.empty() ? "none" : classes) +
         ". Runs ended: " + stops + ". " + lost + ".\n\n";
}

// Attempts and successes by the object each grasp was planned around, most tried first.
std::string by_object(const Json& s) {
  std::vector<std::vector<std::string>> rows;
  for (const Json& o : s.at("by_object")) {
    const std::string classes = counts_text(o.at("reasons"));
    rows.push_back({o.at("name").get<std::string>(), o.at("attempts").dump(),
                    o.at("successes").dump(), classes.empty() ? "-" : classes});
  }
  if (rows.empty()) return "";
  return "By the object each grasp was planned around (the first the cell found between the "
         "planned fingers):\n\n" +
         markdown_table({"object", "attempts", "succeeded", "failures"}, rows) + "\n";
}

// More runs than this get one line about them instead of a row and a bar each.
constexpr std::size_t kRunsShownOneByOne = 20;

std::string runs_in_short(const Json& r) {
  int cleared = 0, errors = 0;
  for (const Json& run : r.at("run_records")) {
    if (run.contains("error")) {
      ++errors;
      continue;
    }
    cleared += run.at("left").get<int>() == 0 ? 1 : 0;
  }
  return std::to_string(r.at("run_records").size()) + " runs: " + std::to_string(cleared) +
         " ended with every object removed" +
         (errors ? ", " + std::to_string(errors) + " with an error" : std::string()) +
         " (each run's cycles are in the JSON report).\n";
}

std::string per_run(const Json& r, const PlotPlace& plots, const std::string& name) {
  if (r.at("run_records").size() > kRunsShownOneByOne) return runs_in_short(r);
  BarChart chart;
  chart.title = "clear the box, per run: " + object_set_name(r.at("objects"));
  chart.value_label = "% of the run's objects / attempts";
  chart.series = {"objects removed", "grasp success"};
  chart.values.resize(2);
  std::vector<std::vector<std::string>> rows;
  for (const Json& run : r.at("run_records")) {
    chart.groups.push_back("seed " + run.at("seed").dump());
    if (run.contains("error")) {
      for (auto& v : chart.values) v.push_back(-1.0);
      rows.push_back({run.at("seed").dump(), "error: " + run.at("error").get<std::string>(), ""});
      continue;
    }
    const int objects = run.at("objects"), attempts = run.at("attempts"),
              removed = run.at("removed");
    chart.values[0].push_back(objects ? 100.0 * removed / objects : 0.0);
    chart.values[1].push_back(attempts ? 100.0 * run.at("successes").get<int>() / attempts : -1.0);
    rows.push_back({run.at("seed").dump(), run.at("summary").get<std::string>(), run.at("stop")});
    if (run.contains("left_objects")) rows.back().push_back(left_objects(run));
  }
  const std::string file = name + "-runs.png";
  write_bar_chart(chart, (std::filesystem::path(plots.dir) / file).string());
  std::vector<std::string> header = {"seed", "run", "ended"};
  if (!rows.empty() && rows.front().size() == 4)
    header.push_back("left (narrowest horizontal extent)");
  for (auto& row : rows) row.resize(header.size());
  return "![per run](" + plots.link + "/" + file + ")\n\n" + markdown_table(header, rows);
}

}  // namespace

ReportSection clutter_section(const Json& report, const std::string& name, const PlotPlace& plots) {
  // Summarised again from the run records, as the bench does: a report an older antipode
  // wrote is reported with today's definitions (the medians of an even count, for one).
  const Json s = summarise_clutter(report.at("run_records"));
  ReportSection section;
  const ClutterProtocol& protocol = protocol_of(report);
  section.title = (protocol.name == "paper"      ? std::string("Dense clutter: ")
                   : protocol.name == "vgn-pile" ? std::string("VGN pile: ")
                                                 : std::string("VGN packed: ")) +
                  object_set_name(report.at("objects"));
  if (const std::string robot = robot_words(report); !robot.empty()) section.title += ", " + robot;
  if (report.contains("gripper"))
    section.title += ", " + report.at("gripper").at("name").get<std::string>();
  if (const std::string classifier = classifier_words(report); !classifier.empty())
    section.title += ", " + classifier;
  if (report.at("tree") != protocol.tree || report.at("noise") != "tree")
    section.title += ", " + setting_words(report, "", "", protocol.tree, "");
  section.markdown = settings_text(report) + command_text(report, name) + headline(report, s) +
                     "\n" + between_runs(report, s) + what_was_left(s) + failures(s) +
                     by_object(s) + per_run(report, plots, name);
  return section;
}

}  // namespace antipode::evaluation
