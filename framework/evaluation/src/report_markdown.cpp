#include "antipode/evaluation/report_markdown.hpp"

#include <cstdio>
#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/core/shipped_data.hpp"
#include "antipode/evaluation/bench_report.hpp"
#include "antipode/robot/robot_file.hpp"

namespace antipode::evaluation {

std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows) {
  const auto line = [](const std::vector<std::string>& cells) {
    std::string out = "|";
    for (const auto& cell : cells) out += " " + cell + " |";
    return out + "\n";
  };
  std::string out = line(header) + "|";
  for (std::size_t i = 0; i < header.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : rows) out += line(row);
  return out;
}

std::string rate_with_interval(int successes, int trials) {
  if (trials <= 0) return "-";
  const auto [lo, hi] = wilson_interval(successes, trials);
  char text[96];
  std::snprintf(text, sizeof text, "%.1f%% [%.1f, %.1f] (%d/%d)", 100.0 * successes / trials,
                100.0 * lo, 100.0 * hi, successes, trials);
  return text;
}

std::string machine_phrase(const nlohmann::ordered_json& report) {
  const auto& m = report.value("machine", nlohmann::ordered_json::object());
  const int cores = m.value("cores", report.value("cores", 0));
  std::string out = std::to_string(cores) + " cores";
  if (m.contains("cpu")) out += " (" + m.at("cpu").get<std::string>() + ")";
  if (m.contains("system")) out += ", " + m.at("system").get<std::string>();
  return out;
}

std::string noise_phrase(const nlohmann::ordered_json& report) {
  const std::string noise = report.value("noise", "tree");
  if (noise == "tree") return "the tree's sensor noise";
  return noise == "0" ? "a noise-free sensor" : "sensor noise x" + noise;
}

std::string setting_words(const nlohmann::ordered_json& report, const std::string& tree_a,
                          const std::string& name_a, const std::string& tree_b,
                          const std::string& name_b) {
  const std::string tree = report.value("tree", ""), noise = report.value("noise", "tree");
  std::string words = tree == tree_a ? name_a : tree == tree_b ? name_b : "tree `" + tree + "`";
  if (noise != "tree")
    words +=
        std::string(words.empty() ? "" : ", ") + (noise == "0" ? "noise-free" : "noise x" + noise);
  return words;
}

std::string robot_words(const nlohmann::ordered_json& report) {
  std::string path;
  for (const auto& entry : report.value("overrides", nlohmann::ordered_json::array()))
    if (const std::string text = entry.get<std::string>(); text.rfind("robot=", 0) == 0)
      path = text.substr(6);
  if (path.empty()) return "";
  if (report.contains("robot") && report.at("robot").contains("name"))
    return report.at("robot").at("name").get<std::string>();
  try {
    return read_robot_file(resolve_shipped(resolve_path(path, report.value("tree", "")))).name;
  } catch (const Error&) {
    return std::filesystem::path(path).stem().string();  // the report outlived the file
  }
}

// Whether the run's classifiers scored hands with the robot file's grasp-success model
// (hog_svm_classifier's `labels`): the tree's `labels` setting as the report records it (an
// override, else the tree's own; reports from before it was recorded: the last override),
// `outcome_or_antipodal` when the robot file names one.
bool robot_success_model_used(const nlohmann::ordered_json& report) {
  std::string labels = report.value("labels", "");
  if (!report.contains("labels"))
    for (const auto& entry : report.value("overrides", nlohmann::ordered_json::array()))
      if (const std::string text = entry.get<std::string>(); text.rfind("labels=", 0) == 0)
        labels = text.substr(7);
  if (labels == "outcome") return true;
  return labels == "outcome_or_antipodal" && report.contains("robot") &&
         report.at("robot").contains("success_model");
}

std::string classifier_words(const nlohmann::ordered_json& report) {
  std::string plugin, model;
  bool probability = false;
  for (const auto& entry : report.value("overrides", nlohmann::ordered_json::array())) {
    const std::string text = entry.get<std::string>();
    if (text.rfind("classifier.plugin=", 0) == 0) plugin = text.substr(18);
    if (text.rfind("classifier.model=", 0) == 0) model = text.substr(17);
    if (text == "classifier.score=probability") probability = true;
  }
  if (!plugin.empty() && plugin != "hog_svm_classifier") {
    if (plugin == "passthrough_classifier") return "no classifier (NC)";
    if (plugin == "antipodal_classifier") return "the antipodal classifier (A)";
    return "classifier `" + plugin + "`";
  }
  if (model.empty() && robot_success_model_used(report)) {
    probability = true;
    // Reports written before the robot's model was recorded name none.
    if (report.contains("robot") && report.at("robot").contains("success_model"))
      model = report.at("robot").at("success_model").get<std::string>();
  }
  if (!probability) return "";
  return "ranked by success probability" +
         (model.empty() ? std::string()
                        : " (`" + std::filesystem::path(model).filename().string() + "`)");
}

std::string object_set_name(const std::string& objects) {
  if (objects == "procedural") return "procedural shapes";
  std::string name = std::filesystem::path(objects).filename().string();
  if (name.empty()) name = std::filesystem::path(objects).parent_path().filename().string();
  return (name == "ycb" ? std::string("YCB") : name) + " objects";
}

std::string shell_word(const std::string& value) {
  const bool plain = !value.empty() && value.find_first_not_of(
                                           "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                           "0123456789._/:=,+-") == std::string::npos;
  if (plain) return value;
  std::string quoted = "'";
  for (char c : value) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string set_options(const nlohmann::ordered_json& report) {
  std::string out;
  for (const auto& entry : report.value("overrides", nlohmann::ordered_json::array()))
    out += " --set " + shell_word(entry.get<std::string>());
  return out;
}

std::string wall_time(double seconds) {
  char text[32];
  if (seconds >= 120.0)
    std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  else
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  return text;
}

}  // namespace antipode::evaluation
