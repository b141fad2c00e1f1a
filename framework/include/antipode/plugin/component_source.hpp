#pragma once
/// @file
/// Where the behaviour-tree loader gets components from. The plugin host implements it;
/// tests may implement it directly.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode {

class ComponentSource {
 public:
  virtual ~ComponentSource() = default;

  /// Every component type name it can create (for "did you mean" suggestions).
  virtual std::vector<std::string> component_types() const = 0;

  /// The kind of `type`, or nullopt when the type is unknown.
  virtual std::optional<ComponentKind> kind_of(const std::string& type) const = 0;

  /// Creates a component of `type`. Throws antipode::Error for an unknown type or bad
  /// parameters (the factory's own message, located in the YAML file). The returned object
  /// keeps whatever it was loaded from alive for as long as it lives.
  virtual std::shared_ptr<Component> create(const std::string& type,
                                            const Parameters& params) const = 0;

  /// Checks the parameters of a component of `type` without making it, as `create` would
  /// (PluginParameterCheck). Returns false when `type` has no such check (the parameters are
  /// then checked only by `create`). Throws antipode::Error for an unknown type or bad
  /// parameters.
  virtual bool check(const std::string& type, const Parameters& params) const {
    (void)type, (void)params;
    return false;
  }
};

}  // namespace antipode
