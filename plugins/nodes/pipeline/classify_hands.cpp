#include <algorithm>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Scores and labels hands with a classifier; fails when no hand is labelled a grasp.
class ClassifyHands final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ClassifyHands",
            bt::NodeCategory::kAction,
            {bt::component_port<Classifier>("classifier", "the classifier to use"),
             bt::input_port<HandSetPtr>("hands", "hypotheses to classify"),
             bt::output_port<HandSetPtr>("classified", "the same hands, scored and labelled")},
            0,
            0,
            "Scores and labels hand hypotheses (paper section 4).",
            {}};
  }

 protected:
  bt::Status tick() override {
    auto classified = std::make_shared<HandSet>(*get_input<HandSetPtr>("hands"));
    component<Classifier>("classifier").classify(*classified, stop_token());
    const auto grasps =
        std::count_if(classified->hands.begin(), classified->hands.end(),
                      [](const Hand& hand) { return hand.label == HandLabel::kPositive; });
    log(std::to_string(grasps) + " of " + std::to_string(classified->hands.size()) +
        " hands classified as grasps");
    set_output("classified", HandSetPtr(std::move(classified)));
    if (grasps == 0) {
      set_failure_reason("no hand was classified as a grasp");
      return bt::Status::kFailure;
    }
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_classify_hands(bt::NodeRegistry& registry) {
  registry.register_node<ClassifyHands>();
}

}  // namespace antipode::pipeline
