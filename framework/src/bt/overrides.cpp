#include "overrides.hpp"

#include "antipode/bt/blackboard.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/yaml_limits.hpp"

namespace antipode::bt::detail {
namespace {

std::vector<std::string> split_path(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (auto dot = text.find('.'); dot != std::string::npos; dot = text.find('.', start)) {
    parts.push_back(text.substr(start, dot - start));
    start = dot + 1;
  }
  parts.push_back(text.substr(start));
  return parts;
}

// A copy of `value` made of new nodes, which carry no position: Parameters::location() tells
// a value given on the command line from one written in the tree file by that.
YAML::Node unmarked(const YAML::Node& value) {
  if (value.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const auto& item : value) out.push_back(unmarked(item));
    return out;
  }
  if (value.IsMap()) {
    YAML::Node out(YAML::NodeType::Map);
    for (const auto& entry : value) out[entry.first.Scalar()] = unmarked(entry.second);
    return out;
  }
  if (value.IsScalar()) return YAML::Node(value.Scalar());
  return YAML::Node(YAML::NodeType::Null);
}

YAML::Node read_value(const std::string& text, const std::string& what) {
  YAML::Node value;
  try {
    value = YAML::Load(text);
  } catch (const YAML::Exception&) {
    return YAML::Node(text);  // not YAML: take it as plain text
  }
  if (!value.IsDefined() || value.IsNull()) return YAML::Node(text);
  check_yaml_size(value, what);  // before unmarked() copies every alias
  return unmarked(value);
}

void set_parameter(YAML::Node& document, const std::string& key, const std::string& text) {
  const std::string what =
      "--set " + key + "=" + (text.size() > 60 ? text.substr(0, 57) + "..." : text);
  const auto path = split_path(key);
  const YAML::Node components = std::as_const(document)["components"];
  std::vector<std::string> names;
  if (components.IsMap()) {
    for (const auto& entry : components) names.push_back(entry.first.Scalar());
  }
  const YAML::Node found = components.IsMap() ? components[path[0]] : YAML::Node();
  if (!found.IsDefined() || !found.IsMap()) {
    throw Error(what + ": unknown component '" + path[0] + "'" + did_you_mean(path[0], names));
  }
  // Non-const nodes all the way down (yaml-cpp: a const lookup of a missing key gives an
  // invalid node, and assigning to a node rebinds nothing - it replaces the value there).
  YAML::Node target = document["components"][path[0]];
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    if (path[i].empty()) throw Error(what + ": empty parameter name");
    YAML::Node child = target[path[i]];
    if (!child.IsMap()) child = YAML::Node(YAML::NodeType::Map);  // a new or replaced entry
    target.reset(child);
  }
  if (path.back().empty()) throw Error(what + ": empty parameter name");
  if (path.size() == 2 && path[1] == "plugin") {
    // Another plugin type: the file's parameters were written for the old one.
    target.reset(YAML::Node(YAML::NodeType::Map));
    document["components"][path[0]] = target;
  }
  target[path.back()] = read_value(text, what);
}

}  // namespace

Overrides apply_overrides(YAML::Node& document, const Overrides& overrides) {
  Overrides entries;
  for (const auto& [key, value] : overrides) {
    if (key.find('.') != std::string::npos) {
      set_parameter(document, key, value);
    } else if (is_valid_key(key)) {
      entries.emplace_back(key, value);
    } else {
      throw Error("--set " + key + "=" + value +
                  ": not a blackboard entry name (a letter or '_', then letters, digits, '_') "
                  "nor component.parameter");
    }
  }
  return entries;
}

}  // namespace antipode::bt::detail
