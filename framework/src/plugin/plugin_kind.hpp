#pragma once
// Plugin-host internals: factory kinds and checks shared by the host's translation units.

#include <memory>
#include <optional>
#include <string>

#include "antipode/interfaces/component.hpp"
#include "antipode/plugin/abi.hpp"

namespace antipode {

/// The ComponentKind spelled `kind` ("sampler", ...), or nullopt ("node" or unknown).
std::optional<ComponentKind> parse_component_kind(const std::string& kind);

/// Why `factory` is malformed, or "" when it is well formed.
std::string factory_problem(const PluginFactory& factory);

/// Calls a plugin's node registration for node type `type`, checking that it registers
/// exactly that type and collides with nothing already registered; every tree using the
/// type then holds `library`.
void register_plugin_node(bt::NodeRegistry& registry, const std::string& type,
                          const std::string& library_path, std::shared_ptr<const void> library,
                          void (*register_node)(bt::NodeRegistry&));

/// True when `type` names a built-in behaviour-tree node.
bool is_builtin_node(const std::string& type);

}  // namespace antipode
