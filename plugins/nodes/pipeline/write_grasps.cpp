#include <algorithm>
#include <vector>

#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "json_output.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json pose_json(const Eigen::Vector3d& position_m, const Eigen::Quaterniond& q) {
  return {{"position_m", vector_json(position_m)},
          {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}}};
}

/// What a robot needs to execute a grasp (docs/pose-convention.md, "Grasp files").
struct Execution {
  double pre_grasp_m = 0.1;     ///< how far back along the approach the pre-grasp lies
  double open_margin_m = 0.01;  ///< opening beyond the grasp's width, on each side
};

/// One hand as documented in docs/pose-convention.md.
nlohmann::json hand_json(const Hand& hand, const HandGeometry& geometry, const Execution& e) {
  const Eigen::Quaterniond q(hand.X_FrameHand.linear());
  const Eigen::Vector3d tcp = hand.position_m() + geometry.depth_m * hand.approach();
  nlohmann::json json = {
      {"position_m", vector_json(hand.position_m())},
      {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
      {"approach", vector_json(hand.approach())},
      {"closing", vector_json(hand.closing())},
      {"axis", vector_json(hand.axis())},
      {"width_m", hand.width_m},
      {"tcp", pose_json(tcp, q)},
      {"pre_grasp", pose_json(tcp - e.pre_grasp_m * hand.approach(), q)},
      {"open_width_m", std::min(geometry.max_aperture_m, hand.width_m + 2.0 * e.open_margin_m)},
      {"score", hand.score},
      {"label", to_string(hand.label)},
      {"sample_index", hand.sample_index},
      {"object", hand.object},
  };
  if (hand.rejection != Rejection::kNone) json["rejection"] = rejection_reason(hand);
  return json;
}

/// Writes hands as JSON (all-or-nothing: a failed write leaves no file).
class WriteGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"WriteGrasps",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("hands", "the hands to write"),
             bt::input_port<std::string>("file", std::string(), "output JSON file; empty = none"),
             bt::input_port<bool>("include_rejected", false,
                                  "also write hands a stage rejected, with the reason"),
             bt::input_port<bool>("ranked", false,
                                  "the hands are in rank order (SelectGrasps' grasps): keep "
                                  "it; otherwise they are written best score first"),
             bt::input_port<double>("pre_grasp_m", 0.1,
                                    "how far back along the approach each grasp's pre-grasp "
                                    "pose lies"),
             bt::input_port<double>("open_margin_m", 0.01,
                                    "the gripper opening to command beyond a grasp's width, "
                                    "on each side (at most the gripper's aperture)")},
            0,
            0,
            "Writes hands to a JSON file (docs/pose-convention.md).",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const HandSetPtr set = get_input<HandSetPtr>("hands");
    const bool include_rejected = get_input<bool>("include_rejected");
    const Execution execution{get_input<double>("pre_grasp_m"), get_input<double>("open_margin_m")};
    if (!(execution.pre_grasp_m >= 0.0 && execution.pre_grasp_m <= 1.0))
      fail("pre_grasp_m", "pre_grasp_m must be in [0, 1] m");
    if (!(execution.open_margin_m >= 0.0 && execution.open_margin_m <= 0.1))
      fail("open_margin_m", "open_margin_m must be in [0, 0.1] m");
    std::vector<const Hand*> order;
    for (const Hand& hand : set->hands) {
      if (include_rejected || hand.rejection == Rejection::kNone) order.push_back(&hand);
    }
    if (!get_input<bool>("ranked")) {
      std::stable_sort(order.begin(), order.end(), [](const Hand* a, const Hand* b) {
        return (a->rejection == Rejection::kNone) > (b->rejection == Rejection::kNone) ||
               ((a->rejection == Rejection::kNone) == (b->rejection == Rejection::kNone) &&
                a->score > b->score);
      });
    }
    nlohmann::json hands = nlohmann::json::array();
    for (const Hand* hand : order) {
      hands.push_back(hand_json(*hand, set->geometry, execution));
      if (hand->rejection == Rejection::kNone) hands.back()["rank"] = hands.size();
    }
    const std::string frame = set->cloud ? set->cloud->frame : std::string();
    const nlohmann::json document = {{"frame", frame}, {"count", hands.size()}, {"hands", hands}};
    write_json_file(file, document);
    log(std::to_string(hands.size()) + " hands written to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_write_grasps(bt::NodeRegistry& registry) { registry.register_node<WriteGrasps>(); }

}  // namespace antipode::pipeline
