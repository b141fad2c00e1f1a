#include "antipode/bt/action_node.hpp"
#include "antipode/core/error.hpp"
#include "draw.hpp"
#include "picture_nodes.hpp"

namespace antipode::pictures {
namespace {

// Seen from above, "up" in the picture is the horizontal direction from the first sensor to
// `centre` (any horizontal direction without a sensor).
Eigen::Vector3d away_from_sensor(const Cloud& cloud, const Eigen::Vector3d& centre,
                                 const Eigen::Vector3d& up) {
  Eigen::Vector3d away = up.unitOrthogonal();
  if (!cloud.view_origins_m.empty()) {
    const Eigen::Vector3d d = centre - cloud.view_origins_m.front().cast<double>();
    const Eigen::Vector3d horizontal = d - d.dot(up) * up;
    if (horizontal.norm() > 1e-6) away = horizontal.normalized();
  }
  return away;
}

/// Draws a cloud from its first sensor and from above (+z up, as in the cell's base frame),
/// with a caption: e.g. the box before and after clearing it.
class DrawCloud final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"DrawCloud",
            bt::NodeCategory::kAction,
            {bt::input_port<CloudPtr>("cloud", "the cloud to draw"),
             bt::input_port<std::string>("file", std::string(), "output PNG file; empty = none"),
             bt::input_port<bt::TextTemplate>("title", bt::TextTemplate{},
                                              "caption; may hold {entries}"),
             bt::input_port<std::vector<double>>(
                 "centre_m", std::vector<double>{},
                 "the point the views centre on [x, y, z]; empty = the cloud's centroid"),
             bt::input_port<double>("extent_m", 0.3, "from the centre to the picture's edge"),
             bt::input_port<int>("size_px", 600, "side of each of the two square views")},
            0,
            0,
            "Draws a cloud from its sensor and from above into a PNG.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const CloudPtr cloud = get_input<CloudPtr>("cloud");
    const int size_px = get_input<int>("size_px");
    if (size_px < 64 || size_px > 4096) fail("size_px", "size_px must be in [64, 4096]");
    const double extent_m = get_input<double>("extent_m");
    if (!(extent_m > 0.0 && extent_m <= 10.0)) fail("extent_m", "extent_m must be in (0, 10]");
    const Eigen::Vector3d centre = centre_of(*cloud);
    const Eigen::Vector3d up = default_up(*cloud);
    const OrthoView sensor_view = view_from_sensor(*cloud, centre, up, extent_m, size_px);
    const OrthoView top_view(-up, away_from_sensor(*cloud, centre, up), centre, extent_m, size_px);
    cv::Mat image(size_px, 2 * size_px, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::Mat left = image(cv::Rect(0, 0, size_px, size_px));
    cv::Mat right = image(cv::Rect(size_px, 0, size_px, size_px));
    draw_cloud(left, sensor_view, *cloud);
    draw_cloud(right, top_view, *cloud);
    const std::string title = expand(get_input<bt::TextTemplate>("title"));
    caption(left, {title.empty() ? "sensor view" : title});
    caption(right, {"from above"});
    write_png(file, image);
    log("picture of " + std::to_string(cloud->size()) + " points written to " + file);
    return bt::Status::kSuccess;
  }

 private:
  Eigen::Vector3d centre_of(const Cloud& cloud) const {
    const auto centre = get_input<std::vector<double>>("centre_m");
    if (centre.size() == 3) return {centre[0], centre[1], centre[2]};
    if (!centre.empty()) fail("centre_m", "centre_m must have 3 numbers");
    return centroid(cloud);
  }
};

}  // namespace

void register_draw_cloud(bt::NodeRegistry& registry) { registry.register_node<DrawCloud>(); }

}  // namespace antipode::pictures
