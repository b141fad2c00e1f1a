// The report's section for an isolation bench (antipode bench isolation): settings and
// command, each variant's success beside the paper's, success per object (table and chart),
// failure classes and seconds per stage.
#include <cstdio>
#include <filesystem>
#include <map>

#include "antipode/core/error.hpp"
#include "antipode/evaluation/bar_chart.hpp"
#include "antipode/evaluation/report_sections.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

// "svm_2v" -> "SVM 2V".
std::string variant_name(const std::string& v) {
  std::string out;
  for (char c : v) out += c == '_' ? ' ' : char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// The paper's real-Baxter figures (section 5.2) per variant.
std::string paper_rate(const std::string& variant) {
  static const std::map<std::string, std::string> paper = {
      {"nc_1v", "57.5%"},
      {"nc_2v", "72.9%"},
      {"a_2v", "94.7% (where A found a grasp)"},
      {"svm_1v", "85.0%"},
      {"svm_2v", "87.8%"}};
  const auto found = paper.find(variant);
  return found == paper.end() ? "-" : found->second;
}

std::vector<std::string> variants_of(const Json& r) {
  auto variants = r.at("variants").get<std::vector<std::string>>();
  if (variants.empty()) throw Error("\"variants\" is empty: the report names no variant");
  return variants;
}

std::string settings_text(const Json& r) {
  // Attempt i runs on seed + i, from attempt `first` on (reports before `first` began at 0).
  const int attempts = r.at("attempts_per_variant");
  const int first = r.at("seed").get<int>() + r.value("first", 0);
  std::string held;
  for (const auto& name : r.at("held_out"))
    held += (held.empty() ? "" : ", ") + name.get<std::string>();
  return r.at("object_names").size() > 0
             ? std::to_string(r.at("object_names").size()) + " " +
                   object_set_name(r.at("objects")) + " in " + r.at("poses").dump() + " poses, " +
                   std::to_string(attempts) + " attempts per variant, seeds " +
                   std::to_string(first) + "-" + std::to_string(first + attempts - 1) + ", tree `" +
                   r.at("tree").get<std::string>() + "`, " + noise_phrase(r) +
                   (held.empty() ? "" : ", held out: " + held) + "; " + machine_phrase(r) + ", " +
                   r.at("jobs").dump() + " process(es), " + wall_time(r.at("wall_s")) +
                   " of wall time.\n\n"
             : "";
}

std::string command_text(const Json& r, const std::string& name) {
  std::string c = "antipode bench isolation --objects " + shell_word(r.at("objects")) +
                  " --poses " + r.at("poses").dump() + " --attempts " +
                  r.at("attempts_per_variant").dump() + " --seed " + r.at("seed").dump();
  if (r.value("first", 0) != 0) c += " --first " + r.at("first").dump();
  std::string variants, held;
  for (const auto& v : r.at("variants"))
    variants += (variants.empty() ? "" : ",") + v.get<std::string>();
  for (const auto& o : r.at("held_out")) held += (held.empty() ? "" : ",") + o.get<std::string>();
  c += " --variants " + variants;
  if (!held.empty()) c += " --held-out " + held;
  if (r.at("tree") != "trees/pick_isolated.yaml") c += " --tree " + shell_word(r.at("tree"));
  if (r.at("noise") != "tree") c += " --noise " + shell_word(r.at("noise"));
  return "```sh\n" + c + set_options(r) + " --jobs " + r.at("jobs").dump() + " --report " + name +
         ".json\n```\n\n";
}

std::string headline(const Json& r) {
  const Json& s = r.at("summary");
  std::vector<std::string> header = {""};
  std::vector<std::vector<std::string>> rows = {{"graspable attempts"},
                                                {"every attempt"},
                                                {"graspable, held-out objects"},
                                                {"not graspable"},
                                                {"where a grasp was found"},
                                                {"executed on graspable objects: held"},
                                                {"the paper (real Baxter, 30 objects)"}};
  for (const auto& v : variants_of(r)) {
    header.push_back(variant_name(v));
    const Json& g = s.at(v).at("groups");
    rows[0].push_back(
        rate_with_interval(g.at("graspable").at("successes"), g.at("graspable").at("attempts")));
    rows[1].push_back(rate_with_interval(s.at(v).at("successes"), s.at(v).at("attempts")));
    rows[2].push_back(
        rate_with_interval(g.at("held_out").at("successes"), g.at("held_out").at("attempts")));
    rows[3].push_back(rate_with_interval(g.at("not_graspable").at("successes"),
                                         g.at("not_graspable").at("attempts")));
    rows[4].push_back(rate_with_interval(s.at(v).at("found_grasp").at("successes"),
                                         s.at(v).at("found_grasp").at("attempts")));
    const Json& f = s.at(v).at("fidelity");
    rows[5].push_back(rate_with_interval(f.at("held"), f.at("executed")) + ", " +
                      f.at("as_detected").dump() + " as detected");
    rows[6].push_back(paper_rate(v));
  }
  // Rows no attempt falls in say nothing.
  for (std::size_t row : {3u, 2u})
    if (rows[row][1] == "-") rows.erase(rows.begin() + std::ptrdiff_t(row));
  return markdown_table(header, rows) + "\n";
}

// Successes / attempts per object and variant, with marks for objects the gripper cannot
// hold in some poses; also drawn as a chart.
std::string per_object(const Json& r, const PlotPlace& plots, const std::string& name) {
  const auto variants = variants_of(r);
  std::vector<std::string> objects;
  std::map<std::string, std::map<std::string, std::pair<int, int>>> cells;
  std::map<std::string, std::pair<int, int>> graspable;  // graspable, all (first variant)
  for (const Json& a : r.at("attempts")) {
    const std::string object = a.at("object");
    if (!cells.count(object)) objects.push_back(object);
    auto& cell = cells[object][a.at("variant").get<std::string>()];
    cell.first += a.at("outcome") == "success" ? 1 : 0;
    ++cell.second;
    if (a.at("variant") == variants.front()) {
      graspable[object].first += a.at("graspable").get<bool>() ? 1 : 0;
      ++graspable[object].second;
    }
  }
  BarChart chart;
  chart.title = "success per object: " + object_set_name(r.at("objects"));
  chart.value_label = "success % (all attempts)";
  chart.groups = objects;
  chart.values.resize(variants.size());
  std::vector<std::string> header = {"object"};
  for (std::size_t v = 0; v < variants.size(); ++v) {
    chart.series.push_back(variant_name(variants[v]));
    header.push_back(variant_name(variants[v]));
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& object : objects) {
    const auto [k_graspable, n_all] = graspable[object];
    std::string label = object;
    if (k_graspable < n_all)
      label += " (graspable in " + std::to_string(k_graspable) + "/" + std::to_string(n_all) + ")";
    rows.push_back({label});
    for (std::size_t v = 0; v < variants.size(); ++v) {
      const auto [k, n] = cells[object][variants[v]];
      rows.back().push_back(n ? std::to_string(k) + "/" + std::to_string(n) : "-");
      chart.values[v].push_back(n ? 100.0 * k / n : -1.0);
    }
  }
  const std::string file = name + "-objects.png";
  write_bar_chart(chart, (std::filesystem::path(plots.dir) / file).string());
  return "![success per object](" + plots.link + "/" + file + ")\n\n" +
         markdown_table(header, rows) + "\n";
}

// Rows of `key` (an object of counts or of seconds per variant) for every variant.
std::string per_variant_rows(const Json& r, const std::string& key, const std::string& first,
                             bool seconds) {
  const auto variants = variants_of(r);
  std::vector<std::string> names, header = {first};
  for (const auto& v : variants) {
    header.push_back(variant_name(v));
    for (const auto& [name, value] : r.at("summary").at(v).at(key).items())
      if (name != "success" && std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& name : names) {
    rows.push_back({name});
    for (const auto& v : variants) {
      const Json& values = r.at("summary").at(v).at(key);
      char text[32];
      if (seconds)
        std::snprintf(text, sizeof text, "%.3f", values.value(name, 0.0));
      else
        std::snprintf(text, sizeof text, "%d", values.value(name, 0));
      rows.back().push_back(text);
    }
  }
  if (rows.empty()) return "none.\n\n";
  return markdown_table(header, rows) + "\n";
}

}  // namespace

ReportSection isolation_section(const Json& report, const std::string& name,
                                const PlotPlace& plots) {
  ReportSection section;
  const std::string robot = robot_words(report);
  section.title =
      "Isolation: " + object_set_name(report.at("objects")) + ", " +
      setting_words(report, "trees/pick_isolated_hand.yaml", "free-floating hand",
                    "trees/pick_isolated.yaml", robot.empty() ? "Baxter's arm" : robot + "'s arm");
  section.markdown = settings_text(report) + command_text(report, name) + headline(report) +
                     per_object(report, plots, name) + "Failures (attempts):\n\n" +
                     per_variant_rows(report, "reasons", "failure class", false) +
                     "Seconds per stage (median):\n\n" +
                     per_variant_rows(report, "stage_s_median", "stage", true);
  return section;
}

}  // namespace antipode::evaluation
