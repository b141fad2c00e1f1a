#include <fstream>

#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

Eigen::Vector3d vector3(const nlohmann::json& json, const char* key) {
  const auto& value = json.at(key);
  if (!value.is_array() || value.size() != 3) throw std::invalid_argument(key);
  return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

/// One hand as WriteGrasps writes it (docs/pose-convention.md).
Hand hand_from_json(const nlohmann::json& json) {
  const auto& q = json.at("quaternion_xyzw");
  if (!q.is_array() || q.size() != 4) throw std::invalid_argument("quaternion_xyzw");
  Hand hand;
  const Eigen::Quaterniond rotation(q[3].get<double>(), q[0].get<double>(), q[1].get<double>(),
                                    q[2].get<double>());
  if (std::abs(rotation.norm() - 1.0) > 1e-3) throw std::invalid_argument("quaternion_xyzw");
  hand.X_FrameHand.linear() = rotation.normalized().toRotationMatrix();
  hand.X_FrameHand.translation() = vector3(json, "position_m");
  hand.width_m = json.value("width_m", 0.0);
  hand.score = json.value("score", 0.0);
  hand.object = json.value("object", -1);
  return hand;
}

/// Reads a grasps JSON file back into a hand set over a given cloud, e.g. to draw grasps
/// found earlier into a scene. An empty file name gives the cloud with no hands.
class ReadGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ReadGrasps",
            bt::NodeCategory::kAction,
            {bt::input_port<CloudPtr>("cloud", "the cloud the grasps belong with"),
             bt::input_port<std::string>("file", std::string(), "grasps JSON; empty = none"),
             bt::output_port<HandSetPtr>("hands", "the grasps over the cloud")},
            0,
            0,
            "Reads grasps written by WriteGrasps.",
            {}};
  }

 protected:
  bt::Status tick() override {
    auto set = std::make_shared<HandSet>();
    set->cloud = get_input<CloudPtr>("cloud");
    const std::string file = get_input<std::string>("file");
    if (!file.empty()) set->hands = read(file, set->cloud->frame);
    set_output("hands", HandSetPtr(std::move(set)));
    return bt::Status::kSuccess;
  }

 private:
  std::vector<Hand> read(const std::string& file, const std::string& frame) const {
    std::ifstream in(file);
    if (!in) fail("file", "cannot read grasps file '" + file + "'");
    std::vector<Hand> hands;
    try {
      const auto document = nlohmann::json::parse(in);
      const std::string grasps_frame = document.at("frame").get<std::string>();
      if (grasps_frame != frame) {
        fail("file", "grasps in '" + file + "' are in frame '" + grasps_frame +
                         "', the cloud is in frame '" + frame + "'");
      }
      for (const auto& json : document.at("hands")) {
        hands.push_back(hand_from_json(json));
        hands.back().frame = frame;
      }
    } catch (const Error&) {
      throw;
    } catch (const std::exception& error) {
      fail("file", "'" + file + "' is not a grasps file (" + error.what() + ")");
    }
    return hands;
  }
};

}  // namespace

void register_read_grasps(bt::NodeRegistry& registry) { registry.register_node<ReadGrasps>(); }

}  // namespace antipode::pipeline
