#pragma once
/// @file
/// Gripper files: one parallel gripper's HandGeometry (hand_geometry.hpp) as a YAML map, so
/// that a gripper is named once and used by training, detection and the benches alike. The
/// shipped ones are in robots/grippers/ (docs/sampling.md, "Grippers"):
///
///     name: 8 cm parallel gripper            # optional: how reports name it
///     finger_width_m: 0.01
///     outer_diameter_m: 0.1
///     depth_m: 0.05
///     height_m: 0.02
///     init_bite_m: 0.01
///     min_aperture_m: 0.002
///     max_aperture_m: 0.08
///     palm_thickness_m: 0.02
///
/// Every length is in metres and every field but `name` is required: a file that left one
/// out would silently describe part of another gripper.

#include <string>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/parameters.hpp"

namespace antipode {

/// A gripper read from a file.
struct GripperFile {
  std::string path;       ///< the file read
  std::string name;       ///< its `name`, or the file's stem when it has none
  HandGeometry geometry;  ///< validated (HandGeometry::validate)
};

/// Reads the gripper file at `path`. Throws antipode::Error with one line naming the file
/// (and the field and line, where there is one) for: a missing, unreadable or non-regular
/// file, YAML that does not parse or is not a map, a missing field, a field that is not a
/// number, an unknown key (with the nearest known one), and a geometry HandGeometry::validate
/// refuses. Thread-safe.
GripperFile read_gripper_file(const std::string& path);

/// The gripper of a `key` parameter (a component's `hand`): either a map of HandGeometry's
/// fields, where absent fields keep the defaults (Baxter's gripper), or the name of a
/// gripper file, resolved with resolve_path() against the parameters' file. No `key` gives
/// the defaults. Errors are located at the parameter (or name the gripper file).
HandGeometry hand_geometry_parameter(const Parameters& params, const std::string& key);

}  // namespace antipode
