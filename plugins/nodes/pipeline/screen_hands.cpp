#include <algorithm>
#include <string>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

/// Marks the hands a selector would drop whatever their score (GraspSelector::screen), so
/// that ClassifyHands describes only the others; fails when none is left.
class ScreenHands final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {
        "ScreenHands",
        bt::NodeCategory::kAction,
        {bt::component_port<GraspSelector>("selector", "the selector that will choose the grasps"),
         bt::input_port<HandSetPtr>("hands", "hand hypotheses (a sampler's)"),
         bt::input_port<CloudPtr>("scene", CloudPtr(),
                                  "the whole capture, in the robot's base frame; "
                                  "default: the hands' cloud"),
         bt::output_port<HandSetPtr>(
             "screened", "the same hands, those the selector rules out with their reason")},
        0,
        0,
        "Screens out, before classification, the hands the selector would drop whatever "
        "their score.",
        {}};
  }

 protected:
  bt::Status tick() override {
    SelectionContext context;
    context.scene = get_input<CloudPtr>("scene");
    context.stop = stop_token();
    const HandSetPtr hands = get_input<HandSetPtr>("hands");
    std::shared_ptr<const HandSet> screened;
    if (const auto error = plugin_error([&] {
          screened = std::make_shared<const HandSet>(
              component<GraspSelector>("selector").screen(*hands, context));
        })) {
      set_failure_reason("the selector failed: " + *error);
      return bt::Status::kFailure;
    }
    if (const std::string problem = screening_problem(*hands, *screened); !problem.empty()) {
      set_failure_reason("the selector " + problem);
      return bt::Status::kFailure;
    }
    const auto left = std::count_if(screened->hands.begin(), screened->hands.end(),
                                    [](const Hand& hand) { return selectable(hand); });
    const std::string dropped = rejection_counts(screened->hands, false);
    log(std::to_string(left) + " of " + std::to_string(screened->hands.size()) +
        " hands left to classify (" + dropped + ")");
    set_output("screened", HandSetPtr(std::move(screened)));
    if (left == 0) {
      set_failure_reason("the selector's screen left no hand (" + dropped + ")");
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_screen_hands(bt::NodeRegistry& registry) { registry.register_node<ScreenHands>(); }

}  // namespace antipode::pipeline
