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

constexpr std::uint32_t kAbiMajor = 10;
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

struct PluginDescriptor {
  std::uint32_t abi_major;
  std::uint32_t abi_minor;
  std::uint32_t descriptor_size;  ///< sizeof(PluginDescriptor) as compiled into the plugin
  const char* name;               ///< plugin library name, e.g. "antipodal_sampler"
  const char* version;            ///< the plugin's own version, e.g. "1.2.0"
  std::uint32_t factory_count;
  const PluginFactory* factories;
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
#define ANTIPODE_PLUGIN(NAME, VERSION, FACTORIES)                                     \
  extern "C" __attribute__((visibility("default"))) const antipode::PluginDescriptor* \
  antipode_plugin_descriptor() {                                                      \
    static const antipode::PluginDescriptor descriptor = {                            \
        antipode::kAbiMajor,                                                          \
        antipode::kAbiMinor,                                                          \
        sizeof(antipode::PluginDescriptor),                                           \
        NAME,                                                                         \
        VERSION,                                                                      \
        static_cast<std::uint32_t>(sizeof(FACTORIES) / sizeof((FACTORIES)[0])),       \
        FACTORIES};                                                                   \
    return &descriptor;                                                               \
  }
