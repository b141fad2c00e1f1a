#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "draw.hpp"
#include "picture_nodes.hpp"

namespace antipode::pictures {
namespace {

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f mm", metres * 1000.0);
  return text;
}

// Splits `text` into lines of at most `width` characters at spaces.
std::vector<std::string> wrapped(const std::string& text, std::size_t width) {
  std::vector<std::string> lines{""};
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!lines.back().empty() && lines.back().size() + 1 + word.size() > width) lines.push_back("");
    lines.back() += (lines.back().empty() ? "" : " ") + word;
    start = end + 1;
  }
  return lines;
}

/// Draws an attempt: the cloud the grasp was found in, the scene's true surfaces when the
/// fingers stopped closing (orange, from a cell that knows them:
/// GraspAttempt::surface_at_closing_m), the planned hand (green) and the hand where it was
/// when the fingers began to close, fingers at the opening where they stopped (red), from
/// the sensor and from the side, with the cell's account of what happened.
class DrawAttempt final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"DrawAttempt",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("grasps", "the selection the grasp was executed from"),
             bt::input_port<GraspAttempt>("attempt", "the cell's record (ExecuteGrasp)"),
             bt::input_port<std::string>("file", std::string(), "output PNG file; empty = none"),
             bt::input_port<bool>("failures_only", true, "draw only attempts that failed"),
             bt::input_port<int>("size_px", 600, "side of each of the two square views")},
            0,
            0,
            "Draws a grasp attempt (planned hand, hand at closing, what happened) into a PNG.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    const GraspAttempt& attempt = get_input_ref<GraspAttempt>("attempt");
    if (file.empty() ||
        (get_input<bool>("failures_only") && attempt.outcome == GraspOutcome::kSuccess))
      return bt::Status::kSuccess;
    const HandSetPtr set = get_input<HandSetPtr>("grasps");
    if (!set->cloud) fail("grasps", "the hand set has no cloud to draw");
    const int size_px = get_input<int>("size_px");
    if (size_px < 64 || size_px > 4096) fail("size_px", "size_px must be in [64, 4096]");
    Hand planned;
    planned.X_FrameHand = attempt.X_BaseHand_planned;
    const Eigen::Vector3d target = grasp_centre(planned, set->geometry);
    const OrthoView sensor_view =
        view_from_sensor(*set->cloud, target, default_up(*set->cloud), 0.15, size_px);
    cv::Mat image(size_px, 2 * size_px, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::Mat left = image(cv::Rect(0, 0, size_px, size_px));
    cv::Mat right = image(cv::Rect(size_px, 0, size_px, size_px));
    render(left, sensor_view, *set, attempt);
    render(right, sensor_view.side_view(), *set, attempt);
    std::vector<std::string> lines = {std::string(to_string(attempt.outcome)) +
                                      (attempt.surface_at_closing_m.empty()
                                           ? " (green: planned, red: at closing)"
                                           : " (green: planned, red: at closing, orange: the "
                                             "true surfaces then)")};
    for (const auto& line : wrapped(attempt.reason, 2 * size_px / 9)) lines.push_back(line);
    caption(image, lines);
    write_png(file, image);
    log("attempt drawn to " + file);
    return bt::Status::kSuccess;
  }

 private:
  static void render(cv::Mat& image, const OrthoView& view, const HandSet& set,
                     const GraspAttempt& attempt) {
    draw_cloud(image, view, *set.cloud);
    draw_points(image, view, attempt.surface_at_closing_m, cv::Scalar(0, 140, 255));
    Hand planned;
    planned.X_FrameHand = attempt.X_BaseHand_planned;
    draw_hand(image, view, make_hand_body(set.geometry), planned, cv::Scalar(40, 170, 40), 2);
    if (attempt.outcome == GraspOutcome::kNotExecuted) return;
    HandGeometry closed = set.geometry;
    if (attempt.opening_at_contact_m > 0.0) closed.max_aperture_m = attempt.opening_at_contact_m;
    Hand at_closing;
    at_closing.X_FrameHand = attempt.X_BaseHand_closing;
    draw_hand(image, view, make_hand_body(closed), at_closing, cv::Scalar(40, 40, 220), 1);
    if (attempt.reached_pose) return;
    cv::putText(image, "stopped " + millimetres(attempt.pose_error_m) + " short",
                {10, image.rows - 12}, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(40, 40, 220), 1,
                cv::LINE_AA);
  }
};

}  // namespace

void register_draw_attempt(bt::NodeRegistry& registry) { registry.register_node<DrawAttempt>(); }

}  // namespace antipode::pictures
