#pragma once
// Markdown pieces of the generated results report (antipode report): tables, rates with
// their intervals, the machine and settings a bench report states.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

/// One section of the report: a level-2 heading and its body.
struct ReportSection {
  std::string title;
  std::string markdown;
};

/// Where a section's PNG plots go: `dir` on disk, `link` the same folder as the markdown
/// file refers to it (relative to the markdown file).
struct PlotPlace {
  std::string dir;
  std::string link;
};

/// A markdown table: header row, then rows.
std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows);

/// "72.9% [61.2, 82.1] (35/48)"; "-" for no trials.
std::string rate_with_interval(int successes, int trials);

/// The "machine" entry of a bench report as a phrase: "2 cores (CPU model), Linux 6.1".
std::string machine_phrase(const nlohmann::ordered_json& report);

/// "the tree's sensor noise" or "sensor noise x0.5" from a report's "noise".
std::string noise_phrase(const nlohmann::ordered_json& report);

/// Words telling a report's tree and noise apart from others': `name_a` for tree `tree_a`,
/// `name_b` for `tree_b` (empty names say nothing), "tree `T`" for any other; then
/// ", noise-free" or ", noise xN" when the report sets the noise.
std::string setting_words(const nlohmann::ordered_json& report, const std::string& tree_a,
                          const std::string& name_a, const std::string& tree_b,
                          const std::string& name_b);

/// The classifier a report's `--set classifier.plugin=P` puts in its tree's place, in the
/// paper's variant words: "no classifier (NC)" for `passthrough_classifier`, "the antipodal
/// classifier (A)" for `antipodal_classifier`, "classifier `P`" for any other; "ranked by
/// success probability (`MODEL`)" when `--set classifier.score=probability` (with the file
/// name of `--set classifier.model=MODEL`, if given); empty when the report keeps the tree's
/// classifier.
std::string classifier_words(const nlohmann::ordered_json& report);

/// The robot a report's `--set robot=FILE` puts in its tree's place: the report's `robot`
/// name, else the robot file's, else the file's stem; empty when the report keeps the tree's.
std::string robot_words(const nlohmann::ordered_json& report);

/// "procedural shapes" or the mesh folder's name ("ycb objects").
std::string object_set_name(const std::string& objects);

/// Shell-quoted `value` when it holds anything but [A-Za-z0-9._/:=,+-].
std::string shell_word(const std::string& value);

/// The `--set` options of a report's "overrides" as command-line text (leading space each).
std::string set_options(const nlohmann::ordered_json& report);

/// Minutes or seconds of wall time: "8.6 min", "48 s".
std::string wall_time(double seconds);

}  // namespace antipode::evaluation
