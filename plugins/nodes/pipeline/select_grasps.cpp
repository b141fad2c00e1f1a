#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Ranks grasps with a selector and outputs the ranking and the best; fails on none.
class SelectGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SelectGrasps",
            bt::NodeCategory::kAction,
            {bt::component_port<GraspSelector>("selector", "the grasp selector to use"),
             bt::input_port<HandSetPtr>("hands", "classified hands"),
             bt::output_port<std::vector<Hand>>("grasps", "grasps worth trying, best first"),
             bt::output_port<Hand>("best", "the first of `grasps`")},
            0,
            0,
            "Selects and ranks grasps (paper section 5.1).",
            {}};
  }

 protected:
  bt::Status tick() override {
    std::vector<Hand> grasps =
        component<GraspSelector>("selector").select(*get_input<HandSetPtr>("hands"));
    log(std::to_string(grasps.size()) + " grasps selected");
    if (grasps.empty()) {
      set_failure_reason("the selector found no grasp");
      return bt::Status::kFailure;
    }
    set_output("best", grasps.front());
    set_output("grasps", std::move(grasps));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_select_grasps(bt::NodeRegistry& registry) { registry.register_node<SelectGrasps>(); }

}  // namespace antipode::pipeline
