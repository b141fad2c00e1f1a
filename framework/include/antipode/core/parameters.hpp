#pragma once
/// @file
/// Typed, validated access to a YAML mapping of parameters (a component's or a node's).
///
/// Every lookup is remembered, so after a constructor has read what it understands it calls
/// reject_unknown(): any key it never asked for is reported with its file position and the
/// nearest known key ("unknown parameter 'sampels' (did you mean 'samples'?)").

#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"

namespace antipode {

class Parameters {
 public:
  Parameters() = default;
  /// `node` must be a map or null. `owner` names the thing configured, for messages, e.g.
  /// "component 'sampler'"; `file` is the YAML file the node came from ("" if none).
  Parameters(const YAML::Node& node, std::string owner, std::string file);

  bool has(const std::string& key) const;

  /// The value at `key` converted to T, or `fallback` when the key is absent.
  template <typename T>
  T get(const std::string& key, const T& fallback) const {
    asked_.insert(key);
    if (!has(key)) return fallback;
    return convert<T>(key);
  }

  /// The value at `key` converted to T; throws Error when absent.
  template <typename T>
  T require(const std::string& key) const {
    asked_.insert(key);
    if (!has(key)) fail(key, "missing required parameter '" + key + "'");
    return convert<T>(key);
  }

  /// The number at `key`, or `fallback` when the key is absent; throws Error located at
  /// `key` ("parameter 'KEY' must be in [LO, HI], got V") unless it is finite and in [lo, hi].
  double number_in(const std::string& key, double fallback, double lo, double hi) const;

  /// Nested parameters at `key` (an empty map when absent).
  Parameters child(const std::string& key) const;

  /// Throws Error for the first key that no get/require/child call asked for.
  void reject_unknown() const;

  /// Throws Error located at `key` (or at the mapping when the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  /// Where `key`'s value is written (or the mapping itself when the key is absent); a value
  /// that came from the command line (`--set`, which leaves no position) is located at "--set".
  SourceLocation location(const std::string& key) const;

  const std::string& owner() const { return owner_; }
  const std::string& file() const { return file_; }
  const YAML::Node& yaml() const { return node_; }

 private:
  template <typename T>
  T convert(const std::string& key) const {
    try {
      return node_[key].as<T>();
    } catch (const YAML::Exception&) {
      fail(key, "parameter '" + key + "' of " + owner_ + " must be " + type_name<T>() + ", got '" +
                    scalar_text(key) + "'");
    }
  }
  std::string scalar_text(const std::string& key) const;
  template <typename T>
  static const char* type_name();

  YAML::Node node_;
  std::string owner_;
  std::string file_;
  mutable std::set<std::string> asked_;
};

/// A file named in a YAML file: `path` as given when it is absolute or exists from the
/// working directory; otherwise from the folder of `yaml_file`, then from that folder's
/// parent (where a tree's `models/`, `scenes/` and `robots/` lie); else as given.
std::string resolve_path(const std::string& path, const std::string& yaml_file);

template <typename T>
const char* Parameters::type_name() {
  if constexpr (std::is_same_v<T, bool>)
    return "true or false";
  else if constexpr (std::is_integral_v<T>)
    return "an integer";
  else if constexpr (std::is_floating_point_v<T>)
    return "a number";
  else if constexpr (std::is_same_v<T, std::string>)
    return "a string";
  else
    return "a list or mapping of the documented form";
}

}  // namespace antipode
