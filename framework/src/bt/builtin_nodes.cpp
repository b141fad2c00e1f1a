#include "control_nodes.hpp"
#include "decorator_nodes.hpp"
#include "leaf_nodes.hpp"

namespace antipode::bt {

void register_builtin_nodes(NodeRegistry& registry) {
  using namespace builtin;
  registry.register_node<Sequence>();
  registry.register_node<ReactiveSequence>();
  registry.register_node<Fallback>();
  registry.register_node<ReactiveFallback>();
  registry.register_node<Parallel>();
  registry.register_node<Inverter>();
  registry.register_node<ForceSuccess>();
  registry.register_node<ForceFailure>();
  registry.register_node<Retry>();
  registry.register_node<Repeat>();
  registry.register_node<KeepRunningUntilFailure>();
  NodeManifest alias = KeepRunningUntilFailure::manifest("RetryUntilFailure");
  alias.create = [](const NodeConfig& config) -> std::unique_ptr<Node> {
    return std::make_unique<KeepRunningUntilFailure>(config);
  };
  registry.add(std::move(alias));
  registry.register_node<Timeout>();
  registry.register_node<SubTree>();
  registry.register_node<AlwaysSuccess>();
  registry.register_node<AlwaysFailure>();
  registry.register_node<SetBlackboard>();
  registry.register_node<Log>();
  registry.register_node<Wait>();
}

NodeRegistry builtin_node_registry() {
  NodeRegistry registry;
  register_builtin_nodes(registry);
  return registry;
}

}  // namespace antipode::bt
