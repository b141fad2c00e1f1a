#include "antipode/io/gripper_file.hpp"

#include <cmath>
#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"
#include "antipode/core/yaml_limits.hpp"

namespace antipode {
namespace {

// The fields of HandGeometry, in the order the header documents them.
struct Field {
  const char* key;
  double HandGeometry::*member;
};
constexpr Field kFields[] = {
    {"finger_width_m", &HandGeometry::finger_width_m},
    {"outer_diameter_m", &HandGeometry::outer_diameter_m},
    {"depth_m", &HandGeometry::depth_m},
    {"height_m", &HandGeometry::height_m},
    {"init_bite_m", &HandGeometry::init_bite_m},
    {"min_aperture_m", &HandGeometry::min_aperture_m},
    {"max_aperture_m", &HandGeometry::max_aperture_m},
    {"palm_thickness_m", &HandGeometry::palm_thickness_m},
};

// Reads the fields present in `p` over `geometry` (all of them when `required`), then
// validates the result; errors are located at the field, or for an inconsistent geometry at
// `owner`'s `key`.
HandGeometry read_fields(const Parameters& p, HandGeometry geometry, bool required,
                         const Parameters& owner, const std::string& key) {
  for (const Field& field : kFields) {
    const double value =
        required ? p.require<double>(field.key) : p.get<double>(field.key, geometry.*field.member);
    if (!std::isfinite(value)) {
      p.fail(field.key, std::string("parameter '") + field.key + "' must be a finite number");
    }
    geometry.*field.member = value;
  }
  try {
    geometry.validate();
  } catch (const Error& error) {
    owner.fail(key, error.message());
  }
  return geometry;
}

}  // namespace

GripperFile read_gripper_file(const std::string& path) {
  const std::string what = "gripper file '" + path + "'";
  const YAML::Node root = load_yaml_map(path, what, "gripper fields", "robots/grippers/");
  const Parameters p(root, what, path);
  GripperFile file;
  file.path = path;
  file.name = p.get<std::string>("name", std::filesystem::path(path).stem().string());
  file.geometry = read_fields(p, HandGeometry{}, true, p, "");
  p.reject_unknown();
  return file;
}

HandGeometry hand_geometry_parameter(const Parameters& params, const std::string& key) {
  if (params.has(key) && params.yaml()[key].IsScalar()) {
    const std::string path = resolve_path(params.get<std::string>(key, ""), params.file());
    try {
      return read_gripper_file(path).geometry;
    } catch (const Error& error) {
      if (error.where().known()) throw;  // located in the gripper file
      params.fail(key, error.message());
    }
  }
  const Parameters p = params.child(key);
  const HandGeometry geometry = read_fields(p, HandGeometry{}, false, params, key);
  p.reject_unknown();
  return geometry;
}

}  // namespace antipode
