#include "plugin_kind.hpp"

#include <array>
#include <cstring>

namespace antipode {

std::optional<ComponentKind> parse_component_kind(const std::string& kind) {
  constexpr std::array<ComponentKind, 5> kKinds = {
      ComponentKind::kSampler, ComponentKind::kClassifier, ComponentKind::kGraspSelector,
      ComponentKind::kMotionPlanner, ComponentKind::kCell};
  for (const ComponentKind candidate : kKinds) {
    if (kind == to_string(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string factory_problem(const PluginFactory& factory) {
  if (factory.kind == nullptr || factory.type == nullptr || factory.type[0] == '\0') {
    return "null kind or empty type name";
  }
  const std::string kind = factory.kind;
  if (kind == "node") {
    if (factory.register_node == nullptr)
      return "node '" + std::string(factory.type) + "' has no register_node function";
    return {};
  }
  if (!parse_component_kind(kind)) {
    return "unknown kind '" + kind +
           "' (expected sampler, classifier, selector, planner, "
           "cell or node)";
  }
  if (factory.create == nullptr) {
    return kind + " '" + factory.type + "' has no create function";
  }
  return {};
}

}  // namespace antipode
