#include "draw.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include <opencv2/imgproc.hpp>

#include "antipode/core/error.hpp"
#include "antipode/io/png_file.hpp"

namespace antipode::pictures {
namespace {

cv::Point2d pixel(const ProjectedPoint& p) { return {p.u_px, p.v_px}; }

}  // namespace

void draw_box(cv::Mat& image, const OrthoView& view, const HandBox& box,
              const Eigen::Isometry3d& X_FrameHand, const cv::Scalar& colour, int thickness) {
  std::array<cv::Point2d, 8> corners;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p_hand((i & 1) ? box.max_m.x() : box.min_m.x(),
                                 (i & 2) ? box.max_m.y() : box.min_m.y(),
                                 (i & 4) ? box.max_m.z() : box.min_m.z());
    corners[i] = pixel(view.project(X_FrameHand * p_hand));
  }
  // The 12 edges join corners that differ in exactly one coordinate bit.
  for (int a = 0; a < 8; ++a) {
    for (int bit : {1, 2, 4}) {
      const int b = a | bit;
      if (b != a) cv::line(image, corners[a], corners[b], colour, thickness, cv::LINE_AA);
    }
  }
}

cv::Scalar object_colour(std::int32_t id) {
  static const cv::Scalar kPalette[] = {// BGR
                                        {40, 40, 220},  {200, 120, 30}, {40, 170, 40},
                                        {200, 40, 200}, {0, 160, 230},  {160, 160, 0},
                                        {120, 60, 160}, {30, 110, 180}};
  if (id < 0) return {150, 150, 150};
  return kPalette[id % 8];
}

namespace {

// Draws `points_m` far to near (nearer ones cover farther ones) as 2 x 2 pixel dots, each in
// colour_of(index, nearness), nearness 1 for the nearest point and 0 for the farthest.
template <class ColourOf>
void draw_far_to_near(cv::Mat& image, const OrthoView& view,
                      const std::vector<Eigen::Vector3f>& points_m, ColourOf colour_of) {
  std::vector<ProjectedPoint> projected(points_m.size());
  for (std::size_t i = 0; i < points_m.size(); ++i)
    projected[i] = view.project(points_m[i].cast<double>());
  std::vector<std::size_t> order(points_m.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return projected[a].depth_m > projected[b].depth_m;
  });
  if (order.empty()) return;
  const double near_m = projected[order.back()].depth_m;
  const double range_m = std::max(projected[order.front()].depth_m - near_m, 1e-6);
  for (const std::size_t i : order) {
    const ProjectedPoint& p = projected[i];
    // Written so that a NaN coordinate is skipped too.
    if (!(p.u_px >= 0 && p.v_px >= 0 && p.u_px < image.cols && p.v_px < image.rows)) continue;
    const double nearness = 1.0 - (p.depth_m - near_m) / range_m;
    cv::rectangle(image, cv::Rect(static_cast<int>(p.u_px), static_cast<int>(p.v_px), 2, 2),
                  colour_of(i, nearness), cv::FILLED);
  }
}

}  // namespace

void draw_points(cv::Mat& image, const OrthoView& view,
                 const std::vector<Eigen::Vector3f>& points_m, const cv::Scalar& colour) {
  draw_far_to_near(image, view, points_m,
                   [&](std::size_t, double nearness) { return colour * (0.55 + 0.45 * nearness); });
}

void draw_cloud(cv::Mat& image, const OrthoView& view, const Cloud& cloud,
                const std::vector<std::int32_t>& object_of_point) {
  draw_far_to_near(image, view, cloud.points_m, [&](std::size_t i, double nearness) {
    if (i < object_of_point.size() && object_of_point[i] >= 0)
      return object_colour(object_of_point[i]) * (0.6 + 0.4 * nearness);
    const double shade = 90.0 + 140.0 * nearness;
    return cv::Scalar(shade, 0.85 * shade, 0.7 * shade);
  });
}

void draw_hand(cv::Mat& image, const OrthoView& view, const HandBody& body, const Hand& hand,
               const cv::Scalar& colour, int thickness) {
  for (const HandBox* box : {&body.finger_minus_y, &body.finger_plus_y, &body.palm}) {
    draw_box(image, view, *box, hand.X_FrameHand, colour, thickness);
  }
}

Eigen::Vector3d centroid(const Cloud& cloud) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : cloud.points_m) sum += p.cast<double>();
  return cloud.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(cloud.size()));
}

Eigen::Vector3d default_up(const Cloud& cloud) {
  return cloud.frame == "sensor" ? Eigen::Vector3d(0, -1, 0) : Eigen::Vector3d(0, 0, 1);
}

OrthoView view_from_sensor(const Cloud& cloud, const Eigen::Vector3d& target,
                           const Eigen::Vector3d& up, double extent_m, int size_px) {
  Eigen::Vector3d origin = target + Eigen::Vector3d::UnitZ();
  if (!cloud.view_origins_m.empty()) origin = cloud.view_origins_m[0].cast<double>();
  Eigen::Vector3d forward = target - origin;
  if (forward.norm() < 1e-6) forward = Eigen::Vector3d::UnitZ();
  return OrthoView(forward, up, target, extent_m, size_px);
}

void write_png(const std::string& file, const cv::Mat& image) {
  if (image.type() != CV_8UC3) throw Error(file + ": a picture must be 8-bit colour");
  write_png_bgr(file, image.cols, image.rows, image.data, image.step[0]);
}

void caption(cv::Mat& image, const std::vector<std::string>& lines) {
  int y = 22;
  for (const std::string& line : lines) {
    cv::putText(image, line, {10, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
    y += 20;
  }
}

}  // namespace antipode::pictures
