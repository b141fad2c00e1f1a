#include <string>

#include "antipode/bt/action_node.hpp"
#include "antipode/interfaces/cell.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Rebuilds a cell's scene; run k of the node (k = 0, 1, ...) uses seed first_seed + k, so a
/// loop around it visits a reproducible series of scenes. `objects` names what the new scene
/// holds, from the cell's ground truth (a simulated cell's), so that log lines can name it.
class ResetScene final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"ResetScene",
            bt::NodeCategory::kAction,
            {bt::component_port<Cell>("cell", "the cell to reset"),
             bt::input_port<std::uint64_t>("first_seed", std::uint64_t{0},
                                           "seed of the first run; later runs count up"),
             bt::output_port<std::uint64_t>("seed", "the seed used"),
             bt::output_port<std::string>(
                 "objects",
                 "the names of the scene's objects, comma-separated ('objects unknown' when the "
                 "cell has no ground truth)")},
            0,
            0,
            "Rebuilds a cell's scene from a seed that counts up run by run.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::uint64_t seed = get_input<std::uint64_t>("first_seed") + run_count() - 1;
    Cell& cell = component<Cell>("cell");
    cell.reset(seed);
    set_output("seed", seed);
    std::string names;
    for (const ObjectTruth& object : cell.object_truth())
      names += (names.empty() ? "" : ", ") + object.name;
    set_output("objects", names.empty() ? std::string("objects unknown") : names);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_reset_scene(bt::NodeRegistry& registry) { registry.register_node<ResetScene>(); }

}  // namespace antipode::pipeline
