#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

// The hands of `in` without a rejection, as a set of their own, and where each came from.
// A hand an earlier stage rejected (ScreenHands) is not worth describing.
HandSet candidates_of(const HandSet& in, std::vector<std::size_t>& where) {
  HandSet candidates{in.cloud, {}, in.geometry, in.support, in.objects};
  for (std::size_t i = 0; i < in.hands.size(); ++i) {
    if (in.hands[i].rejection != Rejection::kNone) continue;
    where.push_back(i);
    candidates.hands.push_back(in.hands[i]);
  }
  return candidates;
}

// `value` as %g writes it (1.5, not to_string's 1.500000).
std::string shortest(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%g", value);
  return text.data();
}

// What is wrong with `out` as a classification of the hands of `in` at `where`: other
// hands, or scores that are not numbers. "" when nothing is.
std::string classification_problem(const HandSet& in, const std::vector<std::size_t>& where,
                                   const HandSet& out) {
  if (out.hands.size() != where.size())
    return "returned " + std::to_string(out.hands.size()) + " hands for " +
           std::to_string(where.size());
  for (std::size_t k = 0; k < out.hands.size(); ++k) {
    const std::size_t i = where[k];
    if (!std::isfinite(out.hands[k].score))
      return "gave hand " + std::to_string(i) + " a score that is not a number";
    if (out.scores == ScoreMeaning::kProbability &&
        !(out.hands[k].score >= 0.0 && out.hands[k].score <= 1.0))
      return "called its scores probabilities but gave hand " + std::to_string(i) + " " +
             shortest(out.hands[k].score) + ", outside [0, 1]";
    if (!out.hands[k].X_FrameHand.matrix().isApprox(in.hands[i].X_FrameHand.matrix()))
      return "moved hand " + std::to_string(i);
  }
  return "";
}

/// Scores and labels hands with a classifier; fails when no hand is labelled a grasp. Hands
/// that already have a rejection pass through as they are.
class ClassifyHands final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ClassifyHands",
            bt::NodeCategory::kAction,
            {bt::component_port<Classifier>("classifier", "the classifier to use"),
             bt::input_port<HandSetPtr>("hands", "hypotheses to classify"),
             bt::output_port<HandSetPtr>(
                 "classified",
                 "the same hands, scored and labelled (those an earlier stage rejected as "
                 "they were)")},
            0,
            0,
            "Scores and labels hand hypotheses (paper section 4); hands an earlier stage "
            "rejected (ScreenHands) are not classified.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr in = get_input<HandSetPtr>("hands");
    std::vector<std::size_t> where;
    HandSet scored = candidates_of(*in, where);
    // A classifier's fault (it threw, or gave back something that is not a classification of
    // these hands) fails this node with the reason; nothing wrong is passed on.
    if (const auto error = plugin_error(
            [&] { component<Classifier>("classifier").classify(scored, stop_token()); })) {
      set_failure_reason("the classifier failed: " + *error);
      return bt::Status::kFailure;
    }
    if (const std::string problem = classification_problem(*in, where, scored); !problem.empty()) {
      set_failure_reason("the classifier " + problem);
      return bt::Status::kFailure;
    }
    // The input's hands in order: the classified ones moved in, the others as they were.
    auto classified =
        std::make_shared<HandSet>(HandSet{in->cloud, {}, in->geometry, in->support, in->objects});
    classified->scores = scored.scores;
    classified->hands.reserve(in->hands.size());
    for (std::size_t i = 0, k = 0; i < in->hands.size(); ++i)
      classified->hands.push_back(k < where.size() && where[k] == i ? std::move(scored.hands[k++])
                                                                    : in->hands[i]);
    const auto grasps =
        std::count_if(classified->hands.begin(), classified->hands.end(),
                      [](const Hand& hand) { return hand.label == HandLabel::kPositive; });
    const std::size_t skipped = in->hands.size() - where.size();
    log(std::to_string(grasps) + " of " + std::to_string(where.size()) +
        " hands classified as grasps" +
        (skipped > 0 ? " (" + std::to_string(skipped) + " rejected before, not classified)" : ""));
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
