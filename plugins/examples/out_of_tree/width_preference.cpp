// A minimal antipode plugin: one classifier and one behaviour-tree node.
//
// - classifier `width_preference`: scores each hand by how close the object width between
//   its fingers is to a preferred width; hands further than `tolerance_m` away are negative,
//   rejected with a reason of the plugin's own ("width far from the preferred").
// - node `CountGrasps`: writes how many hands of a set are labelled positive.
#include <algorithm>
#include <cmath>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/plugin/abi.hpp"

namespace {
using namespace antipode;

class WidthPreference final : public Classifier {
 public:
  explicit WidthPreference(const Parameters& params)
      : preferred_m_(params.get("preferred_width_m", 0.05)),
        tolerance_m_(params.get("tolerance_m", 0.01)) {
    params.reject_unknown();  // "unknown parameter 'x' (did you mean 'y'?)"
    if (tolerance_m_ <= 0.0) params.fail("tolerance_m", "tolerance_m must be > 0");
  }

  void classify(HandSet& set, const StopToken&) const override {
    for (Hand& hand : set.hands) {
      const double distance_m = std::abs(hand.width_m - preferred_m_);
      hand.score = 1.0 - distance_m / tolerance_m_;
      hand.label = distance_m <= tolerance_m_ ? HandLabel::kPositive : HandLabel::kNegative;
      // A reason of the plugin's own: WriteGrasps and `detect --explain` print it.
      if (hand.label == HandLabel::kNegative) reject_for(hand, "width far from the preferred");
    }
  }

 private:
  double preferred_m_;
  double tolerance_m_;
};

class CountGrasps final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"CountGrasps",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("hands", "classified hands"),
             bt::output_port<int>("count", "how many are labelled positive")},
            0,
            0,
            "Counts the hands labelled as grasps.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const HandSetPtr set = get_input<HandSetPtr>("hands");
    const auto count = std::count_if(set->hands.begin(), set->hands.end(),
                                     [](const Hand& h) { return h.label == HandLabel::kPositive; });
    set_output("count", static_cast<int>(count));
    return bt::Status::kSuccess;
  }
};

Component* create_width_preference(const Parameters& params) { return new WidthPreference(params); }
void register_count_grasps(bt::NodeRegistry& registry) { registry.register_node<CountGrasps>(); }
// `antipode validate` checks the parameters with this, without running the tree.
void check_width_preference(const Parameters& params) { const WidthPreference checked(params); }

const PluginFactory kFactories[] = {
    {"classifier", "width_preference", "scores hands by closeness to a preferred width",
     &create_width_preference, nullptr},
    {"node", "CountGrasps", "counts positive hands", nullptr, &register_count_grasps},
};

const PluginParameterCheck kChecks[] = {{"width_preference", &check_width_preference}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("width_preference", "1.0.0", kFactories, kChecks)
