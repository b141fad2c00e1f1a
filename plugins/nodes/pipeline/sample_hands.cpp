#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Samples hand hypotheses from a cloud; fails when there are none.
class SampleHands final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SampleHands",
            bt::NodeCategory::kAction,
            {bt::component_port<Sampler>("sampler", "the sampler to use"),
             bt::input_port<CloudPtr>("cloud", "the cloud to sample"),
             bt::output_port<HandSetPtr>("hands", "the hypotheses, with the cloud they index")},
            0,
            0,
            "Samples hand hypotheses from a cloud (paper section 3).",
            {}};
  }

 protected:
  bt::Status tick() override {
    const CloudPtr cloud = get_input<CloudPtr>("cloud");
    auto hands = std::make_shared<HandSet>(
        component<Sampler>("sampler").sample(*cloud, random(), stop_token()));
    log(std::to_string(hands->hands.size()) + " hand hypotheses from " +
        std::to_string(cloud->size()) + " points");
    if (hands->hands.empty()) {
      set_failure_reason("no hand hypothesis found");
      return bt::Status::kFailure;
    }
    set_output("hands", HandSetPtr(std::move(hands)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_sample_hands(bt::NodeRegistry& registry) { registry.register_node<SampleHands>(); }

}  // namespace antipode::pipeline
