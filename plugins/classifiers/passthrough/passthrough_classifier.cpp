// The classifier `passthrough_classifier`: the paper's "NC" configuration, in which every
// hand hypothesis the sampler produced is taken as a grasp. Labels every hand positive and
// keeps its score (the sampler's) and its rejection reason. No parameters.
#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/plugin/abi.hpp"

namespace {
using namespace antipode;

class PassthroughClassifier final : public Classifier {
 public:
  explicit PassthroughClassifier(const Parameters& params) { params.reject_unknown(); }

  void classify(HandSet& set, const StopToken& stop) const override {
    stop.throw_if_stop_requested("passthrough_classifier");
    for (Hand& hand : set.hands) hand.label = HandLabel::kPositive;
  }
};

Component* create_passthrough(const Parameters& params) {
  return new PassthroughClassifier(params);
}

void check_passthrough(const Parameters& params) { const PassthroughClassifier checked(params); }

const PluginFactory kFactories[] = {
    {"classifier", "passthrough_classifier",
     "labels every hypothesis a grasp, score unchanged (the paper's NC)", &create_passthrough,
     nullptr},
};

const PluginParameterCheck kChecks[] = {{"passthrough_classifier", &check_passthrough}};

}  // namespace

ANTIPODE_PLUGIN_WITH_CHECKS("passthrough_classifier", "1.0.0", kFactories, kChecks)
