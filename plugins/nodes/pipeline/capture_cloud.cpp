#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Captures the named views of a cell as one cloud.
class CaptureCloud final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"CaptureCloud",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell whose sensors capture"),
             bt::input_port<std::vector<std::string>>("views", std::vector<std::string>{},
                                                      "view names; empty = every view"),
             bt::output_port<CloudPtr>("cloud", "the captured cloud, in the cell's base frame")},
            0,
            0,
            "Captures a cloud from a cell's depth views.",
            {}};
  }

 protected:
  bt::Status tick() override {
    Cell& cell = component<Cell>("cell");
    auto views = get_input<std::vector<std::string>>("views");
    if (views.empty()) views = cell.view_names();
    auto cloud = std::make_shared<Cloud>(cell.capture(views));
    if (cloud->empty()) {
      set_failure_reason("the cell's views saw no point");
      return bt::Status::kFailure;
    }
    log(std::to_string(cloud->size()) + " points from " + std::to_string(views.size()) +
        " view(s)");
    set_output("cloud", CloudPtr(std::move(cloud)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_capture_cloud(bt::NodeRegistry& registry) { registry.register_node<CaptureCloud>(); }

}  // namespace antipode::pipeline
