#pragma once
// Grouped bar charts as PNG files, for the generated results report (antipode report).

#include <string>
#include <vector>

namespace antipode::evaluation {

/// Bars in groups: one group per label along the horizontal axis, one bar per series in each
/// group; a value is drawn with its interval when `low`/`high` are given.
struct BarChart {
  std::string title;
  std::string value_label;          ///< e.g. "success %"
  double max_value = 100.0;         ///< top of the value axis
  std::vector<std::string> groups;  ///< labels along the horizontal axis
  std::vector<std::string> series;  ///< one colour each, named in the legend
  /// values[series][group]; a negative value is no bar (no data).
  std::vector<std::vector<double>> values;
  /// Optional intervals, the same shape as `values` (empty: none).
  std::vector<std::vector<double>> low, high;
};

/// Draws `chart` into the PNG file `path` (written atomically). Throws antipode::Error for
/// mismatched shapes or a file that cannot be written.
void write_bar_chart(const BarChart& chart, const std::string& path);

}  // namespace antipode::evaluation
