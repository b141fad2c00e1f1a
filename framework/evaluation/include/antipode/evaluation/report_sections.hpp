#pragma once
// The sections of the generated results report, one per bench report (antipode report).

#include <string>

#include <nlohmann/json.hpp>

#include "antipode/evaluation/report_markdown.hpp"

namespace antipode::evaluation {

/// The section of an isolation bench's report; its charts are written to `plots` as
/// NAME-objects.png.
ReportSection isolation_section(const nlohmann::ordered_json& report, const std::string& name,
                                const PlotPlace& plots);

/// The section of a classifier's evaluation (antipode eval-classifier --report): its ROC area
/// and, for a calibrated model, the calibration by decile, charted to `plots` as
/// NAME-calibration.png.
ReportSection calibration_section(const nlohmann::ordered_json& report, const std::string& name,
                                  const PlotPlace& plots);

/// The section of a clutter bench's report; its chart is written to `plots` as NAME-runs.png.
ReportSection clutter_section(const nlohmann::ordered_json& report, const std::string& name,
                              const PlotPlace& plots);

}  // namespace antipode::evaluation
