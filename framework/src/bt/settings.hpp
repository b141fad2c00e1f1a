#pragma once
// A tree file's `settings`: values named once at the top of the file - the robot, say - that
// its components take as `{name}` and its trees read as entries of the main blackboard.
// `--set name=value` replaces a setting everywhere at once:
//
//     settings:
//       robot: robots/baxter/baxter.yaml
//     components:
//       cell: { plugin: bullet_cell, robot: "{robot}" }
//       planner: { plugin: ompl_planner, robot: "{robot}" }
//
// A setting's value is a scalar (text); a component parameter that is exactly "{name}" takes
// it (in maps and lists of the component too); any other text is left alone.

#include <yaml-cpp/yaml.h>

#include "overrides.hpp"

namespace antipode::bt::detail {

// Applies the file's settings to its components, after `entries` (the `--set key=value`
// overrides) have replaced those they name, and returns `entries` with every setting added
// as an entry of the main blackboard. Throws a located Error for settings that are not a map
// of scalars, a setting whose name is not an entry name, and a component parameter naming
// a setting the file does not have (with the nearest name).
Overrides apply_settings(YAML::Node& document, Overrides entries, const std::string& file);

}  // namespace antipode::bt::detail
