#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Rebuilds a cell's scene; run k of the node (k = 0, 1, ...) uses seed first_seed + k, so a
/// loop around it visits a reproducible series of scenes.
class ResetScene final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ResetScene",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell to reset"),
             bt::input_port<std::uint64_t>("first_seed", std::uint64_t{0},
                                           "seed of the first run; later runs count up"),
             bt::output_port<std::uint64_t>("seed", "the seed used")},
            0,
            0,
            "Rebuilds a cell's scene from a seed that counts up run by run.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::uint64_t seed = get_input<std::uint64_t>("first_seed") + run_count() - 1;
    component<Cell>("cell").reset(seed);
    set_output("seed", seed);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_reset_scene(bt::NodeRegistry& registry) { registry.register_node<ResetScene>(); }

}  // namespace antipode::pipeline
