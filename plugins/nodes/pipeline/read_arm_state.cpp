#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Reads the joint state of a cell's arm; fails for a cell without an arm.
class ReadArmState final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ReadArmState",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell whose arm is read"),
             bt::output_port<JointState>("state", "the arm's joint names and positions")},
            0,
            0,
            "Reads the joint state of a cell's arm.",
            {}};
  }

 protected:
  bt::Status tick() override {
    JointState state = component<Cell>("cell").arm_state();
    if (state.empty()) {
      set_failure_reason("the cell has no arm (set its 'robot')");
      return bt::Status::kFailure;
    }
    set_output("state", std::move(state));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_read_arm_state(bt::NodeRegistry& registry) { registry.register_node<ReadArmState>(); }

}  // namespace antipode::pipeline
