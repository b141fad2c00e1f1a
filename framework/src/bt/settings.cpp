#include "settings.hpp"

#include <map>
#include <string>
#include <vector>

#include "antipode/bt/blackboard.hpp"
#include "antipode/core/error.hpp"
#include "yaml_source.hpp"

namespace antipode::bt::detail {
namespace {

using Settings = std::map<std::string, std::string>;

Settings read_settings(const YAML::Node& node, const std::string& file) {
  Settings settings;
  if (!node.IsDefined() || node.IsNull()) return settings;
  if (!node.IsMap()) {
    throw Error("'settings' must be a mapping of name: value", locate(node, file),
                "for example settings: { robot: robots/baxter/baxter.yaml }");
  }
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    if (!is_valid_key(name)) {
      throw Error("setting '" + name + "': not an entry name (a letter or '_', then letters, " +
                      "digits, '_')",
                  locate(entry.first, file));
    }
    if (!entry.second.IsScalar()) {
      throw Error("setting '" + name + "' must be a single value (text or a number)",
                  locate_value(entry.first, entry.second, file));
    }
    settings[name] = entry.second.Scalar();
  }
  return settings;
}

// The setting a parameter's text names: "{name}" gives name, anything else "".
std::string named_setting(const std::string& text) {
  if (text.size() < 3 || text.front() != '{' || text.back() != '}') return {};
  return text.substr(1, text.size() - 2);
}

std::vector<std::string> names_of(const Settings& settings) {
  std::vector<std::string> names;
  for (const auto& [name, value] : settings) names.push_back(name);
  return names;
}

// Replaces, in place, every scalar of `node` that names a setting by the setting's value.
void substitute(YAML::Node node, const Settings& settings, const std::string& owner,
                const std::string& file) {
  if (node.IsMap()) {
    for (auto entry : node) substitute(entry.second, settings, owner, file);
  } else if (node.IsSequence()) {
    for (auto item : node) substitute(item, settings, owner, file);
  } else if (node.IsScalar()) {
    const std::string name = named_setting(node.Scalar());
    if (name.empty()) return;
    const auto found = settings.find(name);
    if (found == settings.end()) {
      throw Error(owner + ": '{" + name + "}' names no setting of the file" +
                      did_you_mean(name, names_of(settings)),
                  locate(node, file), "add it under 'settings:' at the top of the file");
    }
    node = found->second;
  }
}

}  // namespace

Overrides apply_settings(YAML::Node& document, Overrides entries, const std::string& file) {
  if (!document.IsMap()) return entries;
  Settings settings = read_settings(std::as_const(document)["settings"], file);
  for (const auto& [key, value] : entries) {
    const auto found = settings.find(key);
    if (found != settings.end()) found->second = value;
  }
  const YAML::Node components = std::as_const(document)["components"];
  if (components.IsDefined() && components.IsMap()) {
    for (const auto& component : components) {
      if (!component.second.IsMap()) continue;  // the parser reports it
      substitute(document["components"][component.first.Scalar()], settings,
                 "component '" + component.first.Scalar() + "'", file);
    }
  }
  for (const auto& [name, value] : settings) {
    bool given = false;
    for (const auto& entry : entries) given = given || entry.first == name;
    if (!given) entries.emplace_back(name, value);
  }
  return entries;
}

}  // namespace antipode::bt::detail
