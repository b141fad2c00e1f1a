#include <algorithm>
#include <cmath>
#include <string>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

// What is wrong with `out` as a classification of `in`: other hands, or scores that are
// not numbers. "" when nothing is.
std::string classification_problem(const HandSet& in, const HandSet& out) {
  if (out.hands.size() != in.hands.size())
    return "returned " + std::to_string(out.hands.size()) + " hands for " +
           std::to_string(in.hands.size());
  for (std::size_t i = 0; i < out.hands.size(); ++i) {
    if (!std::isfinite(out.hands[i].score))
      return "gave hand " + std::to_string(i) + " a score that is not a number";
    if (!out.hands[i].X_FrameHand.matrix().isApprox(in.hands[i].X_FrameHand.matrix()))
      return "moved hand " + std::to_string(i);
  }
  return "";
}

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
    const HandSetPtr in = get_input<HandSetPtr>("hands");
    auto classified = std::make_shared<HandSet>(*in);
    // A classifier's fault (it threw, or gave back something that is not a classification of
    // these hands) fails this node with the reason; nothing wrong is passed on.
    if (const auto error = plugin_error(
            [&] { component<Classifier>("classifier").classify(*classified, stop_token()); })) {
      set_failure_reason("the classifier failed: " + *error);
      return bt::Status::kFailure;
    }
    if (const std::string problem = classification_problem(*in, *classified); !problem.empty()) {
      set_failure_reason("the classifier " + problem);
      return bt::Status::kFailure;
    }
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
