// The report's section for a classifier's evaluation (antipode eval-classifier --report): the
// area under the ROC curve and, for a calibrated model, predicted against observed success
// by decile, as a table and a chart (a reliability diagram in bars).
#include <cstdio>
#include <filesystem>

#include "antipode/evaluation/bar_chart.hpp"
#include "antipode/evaluation/report_sections.hpp"

namespace antipode::evaluation {
namespace {

using Json = nlohmann::ordered_json;

std::string percent(double fraction) {
  char text[16];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * fraction);
  return text;
}

std::string command_text(const Json& r, const std::string& name) {
  return "```sh\nantipode eval-classifier --model " + shell_word(r.at("model")) + " --tree " +
         shell_word(r.at("tree")) + set_options(r) + " --report " + name + ".json\n```\n\n";
}

// The deciles as a table, and as a chart written to `plots`.
std::string deciles(const Json& r, const PlotPlace& plots, const std::string& name) {
  BarChart chart;
  chart.title =
      "calibration: " + std::filesystem::path(r.at("model").get<std::string>()).filename().string();
  chart.value_label = "% success";
  chart.series = {"predicted (mean)", "observed"};
  chart.values.resize(2);
  std::vector<std::vector<std::string>> rows;
  int decile = 0;
  for (const Json& bin : r.at("calibration")) {
    const double predicted = bin.at("predicted"), observed = bin.at("observed");
    chart.groups.push_back("decile " + std::to_string(++decile));
    chart.values[0].push_back(100.0 * predicted);
    chart.values[1].push_back(100.0 * observed);
    rows.push_back(
        {std::to_string(decile), percent(predicted), percent(observed), bin.at("count").dump()});
  }
  const std::string file = name + "-calibration.png";
  write_bar_chart(chart, (std::filesystem::path(plots.dir) / file).string());
  return "![calibration by decile](" + plots.link + "/" + file + ")\n\n" +
         markdown_table({"decile of predicted success", "mean predicted", "observed", "trials"},
                        rows);
}

}  // namespace

ReportSection calibration_section(const Json& report, const std::string& name,
                                  const PlotPlace& plots) {
  ReportSection section;
  const std::string model =
      std::filesystem::path(report.at("model").get<std::string>()).filename().string();
  section.title = "Calibration: `" + model + "`";
  for (const Json& entry : report.value("overrides", Json::array()))  // the trials measured on
    if (entry.is_string() && entry.get<std::string>().rfind("trials=", 0) == 0)
      section.title += " on `" + entry.get<std::string>().substr(7) + "`";
  const int examples = report.at("examples"), positives = report.at("positives");
  section.markdown = std::to_string(examples) + " trials, " + std::to_string(positives) +
                     " of them held, tree `" + report.at("tree").get<std::string>() + "`; " +
                     machine_phrase(report) + ".\n\n" + command_text(report, name);
  if (report.contains("roc_auc")) {
    char auc[64];
    std::snprintf(auc, sizeof auc, "Area under the ROC curve %.3f",
                  report.at("roc_auc").get<double>());
    section.markdown += auc;
  }
  if (!report.contains("calibration")) {
    section.markdown += ".\n";  // an uncalibrated model: no probability to compare
    return section;
  }
  char error[96];
  std::snprintf(
      error, sizeof error,
      "; calibration error %.1f points (mean |predicted - observed| over the deciles).\n\n",
      100.0 * report.at("calibration_error").get<double>());
  section.markdown += error + deciles(report, plots, name);
  return section;
}

}  // namespace antipode::evaluation
