#include <nlohmann/json.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "json_output.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Writes the cell's ground truth of its objects as they lie now (Cell::object_truth) to a
/// JSON file, all or nothing: {"frame": "base", "objects": [{"name", "position_m",
/// "quaternion_xyzw", "narrowest_horizontal_m"}]}, poses in the cell's base frame. A cell
/// without ground truth writes an empty list. An empty `file` writes nothing.
class WriteObjects final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"WriteObjects",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell whose objects are written"),
             bt::input_port<std::string>("file", std::string(), "output JSON file; empty = none")},
            0,
            0,
            "Writes where a cell's objects lie to a JSON file.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (const ObjectTruth& object : component<Cell>("cell").object_truth()) {
      const Eigen::Vector3d p = object.X_BaseObject.translation();
      const Eigen::Quaterniond q(object.X_BaseObject.linear());
      objects.push_back({{"name", object.name},
                         {"position_m", {p.x(), p.y(), p.z()}},
                         {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
                         {"narrowest_horizontal_m", object.narrowest_horizontal_m}});
    }
    const nlohmann::ordered_json document = {{"frame", "base"}, {"objects", objects}};
    write_json_file(file, document);
    log(std::to_string(objects.size()) + " objects written to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_write_objects(bt::NodeRegistry& registry) { registry.register_node<WriteObjects>(); }

}  // namespace antipode::pipeline
