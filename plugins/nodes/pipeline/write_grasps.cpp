#include <fstream>

#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/atomic_file.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

/// One hand as documented in docs/pose-convention.md.
nlohmann::json hand_json(const Hand& hand) {
  const Eigen::Quaterniond q(hand.X_FrameHand.linear());
  nlohmann::json json = {
      {"position_m", vector_json(hand.position_m())},
      {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
      {"approach", vector_json(hand.approach())},
      {"closing", vector_json(hand.closing())},
      {"axis", vector_json(hand.axis())},
      {"width_m", hand.width_m},
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
                                  "also write hands a stage rejected, with the reason")},
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
    nlohmann::json hands = nlohmann::json::array();
    for (const Hand& hand : set->hands) {
      if (include_rejected || hand.rejection == Rejection::kNone) hands.push_back(hand_json(hand));
    }
    const std::string frame = set->cloud ? set->cloud->frame : std::string();
    const nlohmann::json document = {{"frame", frame}, {"count", hands.size()}, {"hands", hands}};
    write_file_atomically(file, [&](const std::string& temporary) {
      std::ofstream out(temporary);
      out << document.dump(1) << "\n";
      out.close();  // flushes: a failure to write the last bytes shows here
      if (!out) throw Error("write failed");
    });
    log(std::to_string(hands.size()) + " hands written to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_write_grasps(bt::NodeRegistry& registry) { registry.register_node<WriteGrasps>(); }

}  // namespace antipode::pipeline
