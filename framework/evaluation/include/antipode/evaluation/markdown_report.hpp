#pragma once
// `antipode report`: the results report (docs/results.md) generated from bench reports -
// one section per report with its settings, the command that makes it, tables and PNG
// charts - with hand-written context from a notes file (docs/cli.md, "report").

#include <string>
#include <vector>

namespace antipode::evaluation {

struct ReportOptions {
  std::vector<std::string> reports;  ///< bench JSON reports, one section each, in this order
  std::string out_path;              ///< the markdown file to write
  std::string plots_dir;             ///< PNG charts go here ("" = beside out_path, "images/")
  std::string notes_path;            ///< hand-written context ("" = none)
};

/// Writes the report. Notes: text before the notes' first "## " heading follows the report's
/// introduction; a "## " section whose heading is a generated section's title follows that
/// section's tables; the other sections follow all generated ones, in their order. The charts
/// and the markdown file appear whole or not at all. Returns the charts' folder; throws
/// antipode::Error naming the file at fault.
std::string write_markdown_report(const ReportOptions& options);

}  // namespace antipode::evaluation
