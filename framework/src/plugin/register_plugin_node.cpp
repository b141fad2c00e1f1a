#include <algorithm>

#include "antipode/bt/node_registry.hpp"
#include "antipode/core/error.hpp"
#include "plugin_kind.hpp"

namespace antipode {

bool is_builtin_node(const std::string& type) {
  static const std::vector<std::string> builtin = bt::builtin_node_registry().types();
  return std::binary_search(builtin.begin(), builtin.end(), type);
}

void register_plugin_node(bt::NodeRegistry& registry, const std::string& type,
                          const std::string& library_path, std::shared_ptr<const void> library,
                          void (*register_node)(bt::NodeRegistry&)) {
  if (registry.has(type)) {
    throw Error("plugin " + library_path + " offers node type '" + type +
                "', which is already registered (built-in or another plugin)");
  }
  const std::size_t count_before = registry.types().size();
  register_node(registry);
  if (!registry.has(type) || registry.types().size() != count_before + 1) {
    throw Error("plugin " + library_path + ": the registration function of node '" + type +
                "' must register exactly that one node type");
  }
  registry.keep_loaded(type, std::move(library));
}

}  // namespace antipode
