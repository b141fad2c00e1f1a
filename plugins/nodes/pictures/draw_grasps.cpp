#include <algorithm>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/plugin/abi.hpp"
#include "draw.hpp"
#include "picture_nodes.hpp"

namespace antipode::pictures {
namespace {

// The best `count` candidate hands (no rejection), best first; ties keep their order.
std::vector<const Hand*> best_hands(const HandSet& set, std::size_t count) {
  std::vector<const Hand*> hands;
  for (const Hand& hand : set.hands) {
    if (hand.rejection == Rejection::kNone) hands.push_back(&hand);
  }
  std::stable_sort(hands.begin(), hands.end(),
                   [](const Hand* a, const Hand* b) { return a->score > b->score; });
  if (hands.size() > count) hands.resize(count);
  return hands;
}

// Per cloud point: the id of the object it belongs to, or -1.
std::vector<std::int32_t> object_labels(const HandSet& set) {
  std::vector<std::int32_t> labels(set.cloud->size(), -1);
  for (const SceneObject& object : set.objects) {
    for (const std::int32_t i : object.points) {
      if (i >= 0 && std::size_t(i) < labels.size()) labels[std::size_t(i)] = object.id;
    }
  }
  return labels;
}

// Where the picture looks and how much it shows: around the hands, else the whole cloud.
std::pair<Eigen::Vector3d, double> framing(const Cloud& cloud,
                                           const std::vector<const Hand*>& hands) {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  for (const Hand* hand : hands) target += hand->position_m();
  if (hands.empty())
    target = centroid(cloud);
  else
    target /= static_cast<double>(hands.size());
  double radius_m = 0.0;
  if (hands.empty()) {
    for (const auto& p : cloud.points_m)
      radius_m = std::max(radius_m, (p.cast<double>() - target).norm());
    return {target, std::max(radius_m, 0.05)};
  }
  for (const Hand* hand : hands)
    radius_m = std::max(radius_m, (hand->position_m() - target).norm());
  return {target, std::clamp(radius_m + 0.1, 0.12, 1.0)};
}

/// Draws the cloud and the best hands from the sensor's viewpoint and from the side.
class DrawGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"DrawGrasps",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("hands", "hands and the cloud they came from"),
             bt::input_port<std::string>("file", std::string(), "output PNG file; empty = none"),
             bt::input_port<int>("max_hands", 12, "draw at most this many, best score first"),
             bt::input_port<int>("size_px", 700, "side of each of the two square views"),
             bt::input_port<std::vector<double>>(
                 "up", std::vector<double>{},
                 "up direction [x, y, z]; empty = -y for frame 'sensor', else +z")},
            0,
            0,
            "Draws a cloud with hands as grippers into a PNG (two viewpoints).",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const HandSetPtr set = get_input<HandSetPtr>("hands");
    if (!set->cloud) fail("hands", "the hand set has no cloud to draw");
    const int size_px = get_input<int>("size_px");
    if (size_px < 64 || size_px > 4096) fail("size_px", "size_px must be in [64, 4096]");
    const auto hands =
        best_hands(*set, static_cast<std::size_t>(std::max(0, get_input<int>("max_hands"))));
    const auto [target, extent_m] = framing(*set->cloud, hands);
    const OrthoView sensor_view =
        view_from_sensor(*set->cloud, target, up_direction(*set->cloud), extent_m, size_px);
    cv::Mat image(size_px, 2 * size_px, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::Mat left = image(cv::Rect(0, 0, size_px, size_px));
    cv::Mat right = image(cv::Rect(size_px, 0, size_px, size_px));
    render(left, sensor_view, *set, hands, "sensor view");
    render(right, sensor_view.side_view(), *set, hands, "side view");
    write_png(file, image);
    log("picture of " + std::to_string(hands.size()) + " hands written to " + file);
    return bt::Status::kSuccess;
  }

 private:
  Eigen::Vector3d up_direction(const Cloud& cloud) const {
    const auto up = get_input<std::vector<double>>("up");
    if (up.size() == 3) return {up[0], up[1], up[2]};
    if (!up.empty()) fail("up", "up must have 3 numbers");
    return default_up(cloud);
  }

  void render(cv::Mat& image, const OrthoView& view, const HandSet& set,
              const std::vector<const Hand*>& hands, const std::string& title) const {
    const bool by_object = !set.objects.empty();
    draw_cloud(image, view, *set.cloud,
               by_object ? object_labels(set) : std::vector<std::int32_t>{});
    const HandBody hand_body = make_hand_body(set.geometry);
    // Worst first so the best ends on top, drawn thicker. Without objects the best is green,
    // the others orange; with objects, each hand takes its object's colour.
    for (std::size_t i = hands.size(); i-- > 0;) {
      const bool best = i == 0;
      const cv::Scalar colour = by_object ? object_colour(hands[i]->object)
                                : best    ? cv::Scalar(40, 170, 40)
                                          : cv::Scalar(0, 140, 255);
      draw_hand(image, view, hand_body, *hands[i], colour, best ? 2 : 1);
    }
    const auto candidates = std::count_if(set.hands.begin(), set.hands.end(), [](const Hand& h) {
      return h.rejection == Rejection::kNone;
    });
    std::string text = title + ": best " + std::to_string(hands.size()) + " of " +
                       std::to_string(candidates) + " hands";
    if (static_cast<std::size_t>(candidates) != set.hands.size()) {
      text += " (" + std::to_string(set.hands.size()) + " before classification)";
    }
    caption(image, {text});
  }
};

}  // namespace

void register_draw_grasps(bt::NodeRegistry& registry) { registry.register_node<DrawGrasps>(); }

namespace {

const PluginFactory kFactories[] = {
    {"node", "DrawGrasps", "draws a cloud and hands into a PNG", nullptr, &register_draw_grasps},
    {"node", "DrawAttempt", "draws a grasp attempt: the planned hand and the hand at closing",
     nullptr, &register_draw_attempt},
    {"node", "DrawArmPath", "draws a planned arm motion over the scene", nullptr,
     &register_draw_arm_path},
    {"node", "DrawCloud", "draws a cloud from its sensor and from above", nullptr,
     &register_draw_cloud},
};

}  // namespace
}  // namespace antipode::pictures

ANTIPODE_PLUGIN("picture_nodes", "0.1.0", antipode::pictures::kFactories)
