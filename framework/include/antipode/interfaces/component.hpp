#pragma once
/// @file
/// The base of everything a plugin creates from YAML parameters.

#include <string>

namespace antipode {

/// The kinds of component a plugin may provide. Behaviour-tree nodes are a sixth kind of
/// plugin product but not components (see plugin/abi.hpp).
enum class ComponentKind { kSampler, kClassifier, kGraspSelector, kMotionPlanner, kCell };

/// The YAML / descriptor spelling of a kind: "sampler", "classifier", "selector", "planner",
/// "cell".
const char* to_string(ComponentKind kind);

/// Base class of samplers, classifiers, selectors, planners and cells. Components are created
/// once per tree by their plugin's factory; the tree owns them.
class Component {
 public:
  virtual ~Component() = default;
  virtual ComponentKind kind() const = 0;
};

}  // namespace antipode
