#include "antipode/evaluation/bar_chart.hpp"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "antipode/core/error.hpp"
#include "antipode/io/png_file.hpp"

namespace antipode::evaluation {
namespace {

constexpr int kLeft = 60, kRight = 20, kTop = 50, kBottom = 175;  // margins, pixels
constexpr int kHeight = 420;                                      // of the plot area
constexpr int kGroupWidth = 70;                                   // per group, pixels
// What one chart shows: past these it would be unreadable (and a report listing 20,000
// objects would draw a 1.4-million-pixel-wide image).
constexpr std::size_t kMaxGroups = 60, kMaxSeries = 8, kMaxLabelChars = 40;

const cv::Scalar kInk(40, 40, 40), kGrid(220, 220, 220);

// Distinct colours (BGR) for the series, from the Okabe-Ito palette.
cv::Scalar colour(std::size_t series) {
  static const cv::Scalar palette[] = {{178, 114, 0},  {0, 159, 230},   {115, 158, 0},
                                       {66, 228, 240}, {167, 121, 204}, {0, 94, 213},
                                       {233, 180, 86}, {0, 0, 0}};
  return palette[series % (sizeof palette / sizeof palette[0])];
}

void text(cv::Mat& image, const std::string& s, cv::Point at, double scale = 0.45) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, kInk, 1, cv::LINE_AA);
}

// Text turned a quarter clockwise so it reads downwards from `at` (for long group labels).
void vertical_text(cv::Mat& image, const std::string& s, cv::Point at) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, 0.42, 1, &baseline);
  cv::Mat strip(size.height + baseline + 2, size.width + 2, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(strip, s, {1, size.height + 1}, cv::FONT_HERSHEY_SIMPLEX, 0.42, kInk, 1, cv::LINE_AA);
  cv::Mat turned;
  cv::rotate(strip, turned, cv::ROTATE_90_CLOCKWISE);
  const cv::Rect where(at.x - turned.cols / 2, at.y, turned.cols,
                       std::min(turned.rows, image.rows - at.y));
  turned(cv::Rect(0, 0, where.width, where.height)).copyTo(image(where));
}

void check_shape(const BarChart& c) {
  const auto fits = [&](const std::vector<std::vector<double>>& v, bool optional) {
    if (optional && v.empty()) return true;
    if (v.size() != c.series.size()) return false;
    for (const auto& row : v)
      if (row.size() != c.groups.size()) return false;
    return true;
  };
  if (c.groups.empty() || c.series.empty() || !fits(c.values, false) || !fits(c.low, true) ||
      !fits(c.high, true) || c.low.empty() != c.high.empty() || !(c.max_value > 0.0))
    throw Error("bar chart '" + c.title + "': values do not match its groups and series");
}

void draw_axes(cv::Mat& image, const BarChart& c, int width) {
  for (int tick = 0; tick <= 4; ++tick) {
    const int y = kTop + kHeight - tick * kHeight / 4;
    cv::line(image, {kLeft, y}, {kLeft + width, y}, kGrid, 1);
    char label[32];
    std::snprintf(label, sizeof label, "%g", c.max_value * tick / 4);
    text(image, label, {8, y + 5});
  }
  cv::line(image, {kLeft, kTop}, {kLeft, kTop + kHeight}, kInk, 1);
  cv::line(image, {kLeft, kTop + kHeight}, {kLeft + width, kTop + kHeight}, kInk, 1);
  text(image, c.title, {kLeft, 22}, 0.55);
  text(image, c.value_label, {kLeft, 42});
}

void draw_legend(cv::Mat& image, const BarChart& c) {
  int x = kLeft + 260;
  for (std::size_t s = 0; s < c.series.size(); ++s) {
    cv::rectangle(image, {x, 32}, {x + 12, 44}, colour(s), cv::FILLED);
    text(image, c.series[s], {x + 16, 43});
    int baseline = 0;
    x += 30 + cv::getTextSize(c.series[s], cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline).width;
  }
}

std::string shortened(const std::string& label) {
  return label.size() <= kMaxLabelChars ? label : label.substr(0, kMaxLabelChars - 3) + "...";
}

// `c` cut to what a chart shows: its first kMaxGroups groups and kMaxSeries series, long
// labels shortened; the title says what was left out.
BarChart fitted(BarChart c) {
  const std::size_t groups = c.groups.size(), series = c.series.size();
  const auto cut = [&](std::vector<std::vector<double>>& v) {
    if (v.empty()) return;
    v.resize(std::min(series, kMaxSeries));
    for (auto& row : v) row.resize(std::min(groups, kMaxGroups));
  };
  cut(c.values);
  cut(c.low);
  cut(c.high);
  c.groups.resize(std::min(groups, kMaxGroups));
  c.series.resize(std::min(series, kMaxSeries));
  for (auto* labels : {&c.groups, &c.series})
    for (auto& label : *labels) label = shortened(label);
  if (groups > kMaxGroups)
    c.title += " (the first " + std::to_string(kMaxGroups) + " of " + std::to_string(groups) + ")";
  if (series > kMaxSeries)
    c.title += " (" + std::to_string(kMaxSeries) + " of " + std::to_string(series) + " series)";
  return c;
}

}  // namespace

void write_bar_chart(const BarChart& chart, const std::string& path) {
  check_shape(chart);
  const BarChart c = fitted(chart);
  const int width = std::max(360, int(c.groups.size()) * kGroupWidth);
  cv::Mat image(kTop + kHeight + kBottom, kLeft + width + kRight, CV_8UC3,
                cv::Scalar(255, 255, 255));
  draw_axes(image, c, width);
  draw_legend(image, c);
  const int slot = (kGroupWidth - 14) / int(c.series.size());
  const auto y_of = [&](double v) {
    return kTop + kHeight - int(std::clamp(v / c.max_value, 0.0, 1.0) * kHeight);
  };
  for (std::size_t g = 0; g < c.groups.size(); ++g) {
    const int x0 = kLeft + int(g) * (width / int(c.groups.size())) + 7;
    for (std::size_t s = 0; s < c.series.size(); ++s) {
      const double v = c.values[s][g];
      if (v < 0.0) continue;
      const int x = x0 + int(s) * slot;
      cv::rectangle(image, {x, y_of(v)}, {x + slot - 2, kTop + kHeight}, colour(s), cv::FILLED);
      if (c.low.empty()) continue;
      const int mid = x + (slot - 2) / 2;
      cv::line(image, {mid, y_of(c.low[s][g])}, {mid, y_of(c.high[s][g])}, kInk, 1);
    }
    vertical_text(image, c.groups[g], {x0 + (kGroupWidth - 14) / 2, kTop + kHeight + 6});
  }
  write_png_bgr(path, image.cols, image.rows, image.data, image.step[0]);
}

}  // namespace antipode::evaluation
