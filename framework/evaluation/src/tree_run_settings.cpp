#include <filesystem>
#include <fstream>
#include <iterator>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/evaluation/tree_run_settings.hpp"

namespace antipode::evaluation {

std::vector<std::pair<std::string, std::string>> parse_overrides(
    const std::vector<std::string>& entries) {
  std::vector<std::pair<std::string, std::string>> overrides;
  for (const auto& entry : entries) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw Error("--set '" + entry + "' must have the form key=value", {},
                  "e.g. --set sampler.samples=500");
    }
    overrides.emplace_back(entry.substr(0, equals), entry.substr(equals + 1));
  }
  return overrides;
}

namespace {

// " (did you mean sampler.samples?)" for the components of the file whose parameters include
// `key`, else "".
std::string component_suggestion(const std::string& text, const std::string& key) {
  YAML::Node document;
  try {
    document = YAML::Load(text);
  } catch (const YAML::Exception&) {
    return "";  // loading the tree reports the file's own errors
  }
  std::string names;
  if (document.IsMap() && document["components"] && document["components"].IsMap())
    for (const auto& component : document["components"])
      if (component.second.IsMap() && component.second[key])
        names.append(names.empty() ? "" : " or ")
            .append(component.first.as<std::string>())
            .append(".")
            .append(key);
  return names.empty() ? "" : " (did you mean " + names + "?)";
}

[[noreturn]] void throw_unread_entry(const std::string& tree_path, const std::string& key,
                                     const std::string& value, const std::string& suggestion) {
  throw Error("--set " + key + "=" + value + ": " + tree_path + " never reads {" + key + "}" +
              suggestion + "; a component's parameter is set as COMPONENT.PARAMETER");
}

}  // namespace

void check_entries_are_read(const std::string& tree_path, const std::vector<std::string>& set) {
  if (!std::filesystem::is_regular_file(tree_path)) return;  // loading the tree says what it is
  std::ifstream file(tree_path);
  const std::string text((std::istreambuf_iterator<char>(file)), {});
  for (const auto& [key, value] : parse_overrides(set)) {
    if (key.find('.') != std::string::npos || text.find("{" + key + "}") != std::string::npos)
      continue;
    throw_unread_entry(tree_path, key, value, component_suggestion(text, key));
  }
}

std::string tree_setting(const std::string& tree_path, const std::vector<std::string>& set,
                         const std::string& key) {
  const std::string prefix = key + "=";
  for (auto it = set.rbegin(); it != set.rend(); ++it)
    if (it->rfind(prefix, 0) == 0) return it->substr(prefix.size());
  try {
    const YAML::Node settings = YAML::LoadFile(tree_path)["settings"];
    if (settings.IsDefined() && settings.IsMap() && settings[key].IsDefined() &&
        settings[key].IsScalar())
      return settings[key].Scalar();
  } catch (const YAML::Exception&) {
    // loading the tree reports the file's own errors
  }
  return {};
}

std::string tree_robot_path(const std::string& tree_path, const std::vector<std::string>& set) {
  const std::string robot = tree_setting(tree_path, set, "robot");
  return robot.empty() ? robot : resolve_path(robot, tree_path);
}

}  // namespace antipode::evaluation
