#include <string>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

/// Selects and ranks grasps with a selector; fails when it finds none.
class SelectGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SelectGrasps",
            bt::NodeCategory::kAction,
            {bt::component_port<GraspSelector>("selector", "the grasp selector to use"),
             bt::input_port<HandSetPtr>("hands", "classified hands"),
             bt::input_port<CloudPtr>("scene", CloudPtr(),
                                      "the points a robot arm must avoid, in its base frame "
                                      "(the whole capture); default: the hands' cloud"),
             bt::input_port<JointState>("start", JointState{},
                                        "the arm's joint state (an arm's reach is judged from "
                                        "it); default: none"),
             bt::output_port<HandSetPtr>(
                 "grasps",
                 "the selection: grasps to try first, best first, then every other "
                 "hand with the reason it was not chosen"),
             bt::output_port<Hand>("best", "the best grasp")},
            0,
            0,
            "Selects and ranks grasps (paper section 5.1).",
            {}};
  }

 protected:
  bt::Status tick() override {
    SelectionContext context;
    context.scene = get_input<CloudPtr>("scene");
    context.start = get_input<JointState>("start");
    context.stop = stop_token();
    const HandSetPtr hands = get_input<HandSetPtr>("hands");
    // A selector's fault (it threw, or chose grasps it was not given) fails this node.
    std::shared_ptr<const HandSet> selection;
    if (const auto error = plugin_error([&] {
          selection = std::make_shared<const HandSet>(
              component<GraspSelector>("selector").select(*hands, context));
        })) {
      set_failure_reason("the selector failed: " + *error);
      return bt::Status::kFailure;
    }
    if (const std::string problem = selection_problem(*hands, *selection); !problem.empty()) {
      set_failure_reason("the selector " + problem);
      return bt::Status::kFailure;
    }
    std::size_t chosen = 0;
    while (chosen < selection->hands.size() &&
           selection->hands[chosen].rejection == Rejection::kNone)
      ++chosen;
    log(std::to_string(chosen) + " grasps selected");
    set_output("grasps", HandSetPtr(selection));
    if (chosen == 0) {
      set_failure_reason("the selector found no grasp (" + rejection_counts(selection->hands) +
                         ")");
      return bt::Status::kFailure;
    }
    set_output("best", selection->hands.front());
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_select_grasps(bt::NodeRegistry& registry) { registry.register_node<SelectGrasps>(); }

}  // namespace antipode::pipeline
