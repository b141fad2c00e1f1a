// A node type written against the SDK (docs/trees.md, "Writing node types"): it samples hand
// hypotheses with a sampler component and keeps at most `max_hands` of them. The examples in
// antipode/bt/node.hpp and antipode/bt/ports.hpp are excerpts of this file, which the tests
// compile.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>

#include "antipode/bt/action_node.hpp"
#include "antipode/bt/node_registry.hpp"
#include "antipode/interfaces/sampler.hpp"

namespace my_nodes {
using namespace antipode;
using namespace antipode::bt;

class SampleFewHands : public SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static NodeManifest manifest() {
    return {"SampleFewHands",
            NodeCategory::kAction,
            {component_port<Sampler>("sampler", "the sampler to use"),
             input_port<CloudPtr>("cloud", "the cloud to sample"),
             input_port<int>("max_hands", 1000, "upper bound on the result"),
             output_port<HandSetPtr>("hands", "the sampled hands")},
            0,
            0,
            "Samples at most max_hands hand hypotheses from a cloud.",
            {}};
  }

 protected:
  Status tick() override {
    const auto cloud = get_input<CloudPtr>("cloud");
    auto hands = std::make_shared<HandSet>(
        component<Sampler>("sampler").sample(*cloud, random(), stop_token()));
    if (hands->hands.empty()) {
      set_failure_reason("no hand hypotheses");
      return Status::kFailure;
    }
    const auto max_hands = static_cast<std::size_t>(std::max(0, get_input<int>("max_hands")));
    if (hands->hands.size() > max_hands) hands->hands.resize(max_hands);
    set_output("hands", HandSetPtr(std::move(hands)));
    return Status::kSuccess;
  }
};

}  // namespace my_nodes

// A plugin's node factory calls this (plugin/abi.hpp, docs/plugins.md).
void register_my_nodes(antipode::bt::NodeRegistry& registry) {
  registry.register_node<my_nodes::SampleFewHands>();
}
