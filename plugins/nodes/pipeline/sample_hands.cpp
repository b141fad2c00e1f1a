#include <cstdio>
#include <string>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/sampler.hpp"
#include "nodes.hpp"
#include "plugin_output_checks.hpp"

namespace antipode::pipeline {
namespace {

// Why a cloud may give no hand: coordinates in other units than metres. The gripper is a few
// centimetres across; a cloud tens of metres across is almost always in millimetres.
std::string units_hint(const Cloud& cloud) {
  if (cloud.points_m.empty()) return {};
  Eigen::Vector3f lo = cloud.points_m.front(), hi = lo;
  for (const Eigen::Vector3f& p : cloud.points_m) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const float extent_m = (hi - lo).maxCoeff();
  if (extent_m <= 20.0f) return {};
  char text[160];
  std::snprintf(text, sizeof(text),
                "; the cloud is %.0f m across, and coordinates must be in metres: scale a cloud "
                "in millimetres by 0.001",
                static_cast<double>(extent_m));
  return text;
}

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
    // The sampler's errors are about the cloud (no finite point, nothing in the workspace):
    // they stop the run as input errors, located at this node. Broken hands fail the node.
    auto hands = std::make_shared<HandSet>(
        component<Sampler>("sampler").sample(*cloud, random(), stop_token()));
    if (const std::string problem = sampling_problem(*hands); !problem.empty()) {
      set_failure_reason("the sampler " + problem);
      return bt::Status::kFailure;
    }
    log(std::to_string(hands->hands.size()) + " hand hypotheses from " +
        std::to_string(cloud->size()) + " points" +
        (hands->objects.empty() || !hands->support
             ? std::string()
             : " on " + std::to_string(hands->objects.size()) +
                   " objects standing on the support (a plane of " +
                   std::to_string(hands->support->inliers) + " of the " +
                   std::to_string(hands->cloud->size()) + " points after preprocessing)"));
    if (hands->hands.empty()) {
      set_failure_reason("no hand hypothesis found" + units_hint(*cloud));
      return bt::Status::kFailure;
    }
    set_output("hands", HandSetPtr(std::move(hands)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_sample_hands(bt::NodeRegistry& registry) { registry.register_node<SampleHands>(); }

}  // namespace antipode::pipeline
