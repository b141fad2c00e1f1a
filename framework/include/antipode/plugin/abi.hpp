#pragma once
/// @file
/// The binary contract between the plugin host and a plugin library.
///
/// A plugin library exports exactly one C symbol, `antipode_plugin_descriptor`, returning a
/// pointer to a static PluginDescriptor. The host checks, in this order, before using
/// anything else in it: the ABI major equals the host's, the ABI minor is not newer than
/// the host's, `descriptor_size` is at least the size of the fields the host reads, and no
/// type name collides with one already loaded. Any failure refuses the whole library with
/// a message naming its path (see docs/plugins.md).
///
/// Bump kAbiMajor for any change that breaks existing plugins (layout of these structs, the
/// interfaces in antipode/interfaces/, the node API in antipode/bt/); bump kAbiMinor for
/// additions old plugins need not know about.

#include <cstdint>

namespace antipode {

class Component;
class Parameters;
namespace bt {
class NodeRegistry;
}

constexpr std::uint32_t kAbiMajor = 13;
constexpr std::uint32_t kAbiMinor = 0;

/// One thing a plugin can make. For a component kind ("sampler", "classifier", "selector",
/// "planner", "cell") `create` is set and `register_node` is null; for kind "node" it is the
/// other way round.
struct PluginFactory {
  const char* kind;     ///< "sampler" | "classifier" | "selector" | "planner" | "cell" | "node"
  const char* type;     ///< unique type name, e.g. "antipodal_sampler"
  const char* summary;  ///< one line for `antipode plugins`
  /// Creates a component from its parameters; throws antipode::Error for bad parameters.
  /// The host takes ownership and deletes it with `delete` through Component's virtual
  /// destructor (so the object must come from the plugin's own `new`).
  Component* (*create)(const Parameters& params);
  /// Registers the behaviour-tree node type `type` (its ports and constructor).
  void (*register_node)(bt::NodeRegistry& registry);
};

/// A check of one component type's parameters, without making the component (optional): it reads
/// every parameter `create` reads and throws the antipode::Error `create` would throw for a bad one
/// - an unknown key, a value out of range, a file that cannot be read - but builds nothing heavy
/// (no world, no planner, no index over a model). `antipode validate` calls it for every component
/// a tree declares; a type without one is checked only when the tree loads.
struct PluginParameterCheck {
  const char* type;  ///< a component type among this plugin's factories
  void (*check)(const Parameters& params);
};

struct PluginDescriptor {
  std::uint32_t abi_major;
  std::uint32_t abi_minor;
  std::uint32_t descriptor_size;  ///< sizeof(PluginDescriptor) as compiled into the plugin
  const char* name;               ///< plugin library name, e.g. "antipodal_sampler"
  const char* version;            ///< the plugin's own version, e.g. "1.2.0"
  std::uint32_t factory_count;
  const PluginFactory* factories;
  // Since ABI 10.1; the host reads them only when `descriptor_size` covers them.
  std::uint32_t check_count;
  const PluginParameterCheck* checks;  ///< null when check_count is 0
};

}  // namespace antipode

/// The entry symbol's name and signature.
#define ANTIPODE_PLUGIN_ENTRY antipode_plugin_descriptor
extern "C" {
typedef const antipode::PluginDescriptor* (*antipode_plugin_entry_fn)();
}

/// Defines the entry symbol for a plugin named NAME with version VERSION offering the
/// PluginFactory array FACTORIES (a static array in the plugin):
///   static const antipode::PluginFactory kFactories[] = {{...}, {...}};
///   ANTIPODE_PLUGIN("my_plugin", "1.0.0", kFactories)
#define ANTIPODE_PLUGIN(NAME, VERSION, FACTORIES) \
  ANTIPODE_PLUGIN_DESCRIPTOR_(NAME, VERSION, FACTORIES, 0, nullptr)

/// As ANTIPODE_PLUGIN, with the PluginParameterCheck array CHECKS (a static array in the
/// plugin) for some or all of its component types:
///   static const antipode::PluginParameterCheck kChecks[] = {{"my_sampler", &check}};
///   ANTIPODE_PLUGIN_WITH_CHECKS("my_plugin", "1.0.0", kFactories, kChecks)
#define ANTIPODE_PLUGIN_WITH_CHECKS(NAME, VERSION, FACTORIES, CHECKS)                           \
  ANTIPODE_PLUGIN_DESCRIPTOR_(NAME, VERSION, FACTORIES,                                         \
                              static_cast<std::uint32_t>(sizeof(CHECKS) / sizeof((CHECKS)[0])), \
                              CHECKS)

/// The entry symbol both macros define (not for direct use).
#define ANTIPODE_PLUGIN_DESCRIPTOR_(NAME, VERSION, FACTORIES, CHECK_COUNT, CHECKS)    \
  extern "C" __attribute__((visibility("default"))) const antipode::PluginDescriptor* \
  antipode_plugin_descriptor() {                                                      \
    static const antipode::PluginDescriptor descriptor = {                            \
        antipode::kAbiMajor,                                                          \
        antipode::kAbiMinor,                                                          \
        sizeof(antipode::PluginDescriptor),                                           \
        NAME,                                                                         \
        VERSION,                                                                      \
        static_cast<std::uint32_t>(sizeof(FACTORIES) / sizeof((FACTORIES)[0])),       \
        FACTORIES,                                                                    \
        CHECK_COUNT,                                                                  \
        CHECKS};                                                                      \
    return &descriptor;                                                               \
  }
