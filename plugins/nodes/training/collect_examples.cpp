#include "antipode/bt/action_node.hpp"
#include "antipode/grasp/training_examples.hpp"
#include "nodes.hpp"

namespace antipode::training {
namespace {

/// Appends the HOG descriptors of labelled hands to a training set: per positive or negative
/// hand, one from each listed view's points and one from all of them (paper section 4.3).
/// Hands found in one view, given as LabelHands' `judged` set (their closing points in the
/// registered cloud they were labelled against), give C1, C2 and C12 descriptors too.
class CollectExamples final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {
        "CollectExamples",
        bt::NodeCategory::kAction,
        {bt::input_port<HandSetPtr>("hands", "labelled hands (LabelHands)"),
         bt::input_port<TrainingSetPtr>("dataset", "the training set to append to"),
         bt::input_port<std::vector<int>>("single_views", std::vector<int>{0, 1},
                                          "views whose points alone make a descriptor"),
         bt::input_port<bool>("all_views", true, "also a descriptor of all the points"),
         bt::input_port<int>("min_points", 10, "fewer closing points in a view give no descriptor"),
         bt::input_port<int>("max_hands_per_label", 0,
                             "at most this many positive and negative hands, drawn at "
                             "random (0: all)"),
         bt::input_port<std::uint64_t>("source", std::uint64_t{0},
                                       "scene id recorded with the examples"),
         bt::input_port<int>("threads", 0, "workers (0: all cores)")},
        0,
        0,
        "Appends HOG descriptors of labelled hands to a training set.",
        {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr hands = get_input<HandSetPtr>("hands");
    const TrainingSetPtr set = get_input<TrainingSetPtr>("dataset");
    ExampleOptions options;
    options.single_views = get_input<std::vector<int>>("single_views");
    options.all_views = get_input<bool>("all_views");
    const int min_points = get_input<int>("min_points");
    if (min_points < 1) fail("min_points", "min_points must be at least 1");
    options.min_points = static_cast<std::size_t>(min_points);
    options.threads = get_input<int>("threads");
    const int max_hands = get_input<int>("max_hands_per_label");
    if (max_hands < 0) fail("max_hands_per_label", "max_hands_per_label must be 0 or more");
    options.max_hands_per_label = static_cast<std::size_t>(max_hands);
    const auto source = static_cast<std::int32_t>(get_input<std::uint64_t>("source"));
    const ExampleCounts counts = add_examples(*hands, options, source, random(), *set);
    log(std::to_string(counts.positive_examples) + " positive and " +
        std::to_string(counts.negative_examples) + " negative examples from " +
        std::to_string(counts.positive_hands) + " + " + std::to_string(counts.negative_hands) +
        " hands; " + std::to_string(set->size()) + " in all");
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_collect_examples(bt::NodeRegistry& registry) {
  registry.register_node<CollectExamples>();
}

}  // namespace antipode::training
