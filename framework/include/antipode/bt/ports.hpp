#pragma once
/// @file
/// Port declarations: what a node type reads and writes, and how its YAML keys are checked.
///
/// A node type lists its ports in its NodeManifest (from docs/examples/sample_few_hands.cpp):
/// @code
///   static NodeManifest manifest() {
///     return {"SampleFewHands",
///             NodeCategory::kAction,
///             {component_port<Sampler>("sampler", "the sampler to use"),
///              input_port<CloudPtr>("cloud", "the cloud to sample"),
///              input_port<int>("max_hands", 1000, "upper bound on the result"),
///              output_port<HandSetPtr>("hands", "the sampled hands")},
///             0,
///             0,
///             "Samples at most max_hands hand hypotheses from a cloud.",
///             {}};
///   }
/// @endcode

#include <any>
#include <chrono>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <typeindex>
#include <vector>

#include "antipode/bt/converters.hpp"
#include "antipode/bt/status.hpp"
#include "antipode/interfaces/cell.hpp"
#include "antipode/interfaces/classifier.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/grasp_selector.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "antipode/interfaces/sampler.hpp"

namespace antipode::bt {

/// One port of a node type.
struct PortInfo {
  std::string name;
  PortDirection direction = PortDirection::kInput;
  std::type_index type = std::type_index(typeid(void));
  std::string type_name;  ///< readable form of `type`, for messages and docs
  bool required = false;  ///< the YAML must give a value (inputs without default, in-outs)
  std::optional<std::string> default_text;  ///< the default as written in docs
  std::any default_value;                   ///< the default itself (of type `type`)
  std::string description;
  /// Set for component ports: the value is a literal component name whose component must be
  /// of this kind.
  std::optional<ComponentKind> component_kind;
};

/// The ComponentKind of an interface class (Sampler, Classifier, GraspSelector,
/// MotionPlanner, Cell).
template <typename C>
constexpr ComponentKind component_kind_of() {
  if constexpr (std::is_same_v<C, Sampler>)
    return ComponentKind::kSampler;
  else if constexpr (std::is_same_v<C, Classifier>)
    return ComponentKind::kClassifier;
  else if constexpr (std::is_same_v<C, GraspSelector>)
    return ComponentKind::kGraspSelector;
  else if constexpr (std::is_same_v<C, MotionPlanner>)
    return ComponentKind::kMotionPlanner;
  else {
    static_assert(std::is_same_v<C, Cell>, "C must be one of the component interfaces");
    return ComponentKind::kCell;
  }
}

namespace detail {

template <typename T, typename = void>
struct Streamable : std::false_type {};
template <typename T>
struct Streamable<T, std::void_t<decltype(std::declval<std::ostream&>() << std::declval<T>())>>
    : std::true_type {};

template <typename T>
struct IsVector : std::false_type {};
template <typename T>
struct IsVector<std::vector<T>> : std::true_type {};
template <typename T>
struct IsSharedPtr : std::false_type {};
template <typename T>
struct IsSharedPtr<std::shared_ptr<T>> : std::true_type {};

// The documented text of a typed default value: YAML for lists, "unset" for a null pointer.
template <typename T>
std::string default_text_of(const T& value) {
  if constexpr (IsVector<T>::value) {
    std::string text = "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      text += (i == 0 ? "" : ", ") + default_text_of(value[i]);
    }
    return text + "]";
  } else if constexpr (IsSharedPtr<T>::value) {
    return value == nullptr ? "unset" : "(" + type_name<T>() + ")";
  } else if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_same_v<T, std::chrono::milliseconds>) {
    return std::to_string(value.count());
  } else if constexpr (Streamable<T>::value) {
    std::ostringstream text;
    text << value;
    return text.str();
  } else {
    return "(" + type_name<T>() + ")";
  }
}

template <typename T>
PortInfo make_port(std::string name, PortDirection direction, bool required,
                   std::string description) {
  PortInfo port;
  port.name = std::move(name);
  port.direction = direction;
  port.type = std::type_index(typeid(T));
  port.type_name = type_name<T>();
  port.required = required;
  port.description = std::move(description);
  return port;
}

}  // namespace detail

/// A required input port: the YAML must give a literal or a `{key}` reference.
template <typename T>
PortInfo input_port(std::string name, std::string description) {
  return detail::make_port<T>(std::move(name), PortDirection::kInput, true, std::move(description));
}

/// An optional input port with a default used when the YAML does not give the port.
template <typename T>
PortInfo input_port(std::string name, T default_value, std::string description) {
  PortInfo port =
      detail::make_port<T>(std::move(name), PortDirection::kInput, false, std::move(description));
  port.default_text = detail::default_text_of(default_value);
  port.default_value = std::move(default_value);
  return port;
}

/// An optional input port whose default is written as YAML text, e.g. "{cloud}" to read an
/// entry when the port is not given, or "[1, 2]" for a list.
template <typename T>
PortInfo input_port_text_default(std::string name, std::string default_text,
                                 std::string description) {
  PortInfo port =
      detail::make_port<T>(std::move(name), PortDirection::kInput, false, std::move(description));
  port.default_text = std::move(default_text);
  return port;
}

/// An output port: its value names the blackboard entry written (`{key}` or just `key`).
/// Output ports are optional; writing to an output the YAML did not connect does nothing.
template <typename T>
PortInfo output_port(std::string name, std::string description) {
  return detail::make_port<T>(std::move(name), PortDirection::kOutput, false,
                              std::move(description));
}

/// A required port that reads and writes the same blackboard entry.
template <typename T>
PortInfo inout_port(std::string name, std::string description) {
  return detail::make_port<T>(std::move(name), PortDirection::kInOut, true, std::move(description));
}

/// A required input port naming a component declared under `components:`; the loader checks
/// that the component exists and is a C (Sampler, Classifier, GraspSelector, MotionPlanner
/// or Cell). Read it with Node::component<C>(name).
template <typename C>
PortInfo component_port(std::string name, std::string description) {
  PortInfo port = detail::make_port<std::string>(std::move(name), PortDirection::kInput, true,
                                                 std::move(description));
  port.component_kind = component_kind_of<C>();
  port.type_name = std::string(to_string(*port.component_kind)) + " component";
  return port;
}

}  // namespace antipode::bt
