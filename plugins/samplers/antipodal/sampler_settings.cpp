#include "sampler_settings.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "antipode/geometry/bin.hpp"
#include "antipode/io/gripper_file.hpp"
#include "antipode/robot/robot_file.hpp"

namespace antipode::samplers {
namespace {

Eigen::Vector3f vector3(const Parameters& params, const std::string& key,
                        const Eigen::Vector3f& fallback) {
  if (!params.has(key)) {
    params.get<std::vector<double>>(key, {});  // marks the key as known
    return fallback;
  }
  const auto values = params.get<std::vector<double>>(key, {});
  if (values.size() != 3) params.fail(key, "parameter '" + key + "' must be a list [x, y, z]");
  for (const double v : values) {
    if (!std::isfinite(v)) params.fail(key, "parameter '" + key + "' must be finite");
  }
  return Eigen::Vector3d(values[0], values[1], values[2]).cast<float>();
}

std::optional<AxisBox> box(const Parameters& params, const std::string& key) {
  const Parameters child = params.child(key);
  if (!params.has(key)) return std::nullopt;
  for (const char* corner : {"min", "max"}) {
    if (!child.has(corner)) params.fail(key, "parameter '" + key + "' needs min and max");
  }
  AxisBox result{vector3(child, "min", Eigen::Vector3f::Zero()),
                 vector3(child, "max", Eigen::Vector3f::Zero())};
  child.reject_unknown();
  for (int axis = 0; axis < 3; ++axis) {
    if (result.min_m[axis] > result.max_m[axis]) {
      params.fail(key,
                  "parameter '" + key + "': min " + "xyz"[axis] + " is above max " + "xyz"[axis]);
    }
  }
  return result;
}

// A number with a lower bound (inclusive or not).
double number(const Parameters& params, const std::string& key, double fallback, double lower,
              bool inclusive) {
  const double value = params.get<double>(key, fallback);
  if (!std::isfinite(value) || value < lower || (!inclusive && value == lower)) {
    params.fail(key, "parameter '" + key + "' must be " + (inclusive ? ">= " : "> ") +
                         std::to_string(lower) + ", got " + std::to_string(value));
  }
  return value;
}

int integer(const Parameters& params, const std::string& key, int fallback, int lower) {
  const int value = params.get<int>(key, fallback);
  if (value < lower) {
    params.fail(key, "parameter '" + key + "' must be at least " + std::to_string(lower) +
                         ", got " + std::to_string(value));
  }
  return value;
}

SupportPlaneMode support_mode(const Parameters& params) {
  const std::string value = params.get<std::string>("support_plane", "auto");
  if (value == "auto") return SupportPlaneMode::kAuto;
  if (value == "none") return SupportPlaneMode::kNone;
  params.fail("support_plane",
              "parameter 'support_plane' must be 'auto' or 'none', got '" + value + "'");
  return SupportPlaneMode::kNone;
}

HandSearchParameters search_parameters(const Parameters& params) {
  HandSearchParameters s;
  // The gripper: `hand`, else the robot file's, else Baxter's (HandGeometry's defaults).
  const bool robot_gripper = params.has("robot") && !params.has("hand");
  s.hand = robot_gripper ? robot_file_parameter(params, "robot").gripper
                         : hand_geometry_parameter(params, "hand");
  (void)params.get<std::string>("robot", "");  // a `hand` given beside it replaces its gripper
  s.samples = static_cast<std::size_t>(integer(params, "samples", 4000, 1));
  s.frame_radius_m = number(params, "neighbourhood_radius_m", s.frame_radius_m, 0.0, false);
  s.frame.min_points = static_cast<std::size_t>(integer(params, "min_neighbours", 10, 9));
  s.orientations = integer(params, "orientations", s.orientations, 1);
  s.positions = integer(params, "positions", s.positions, 1);
  s.approach_tilts_deg = params.get<std::vector<double>>("approach_tilts_deg", {});
  s.tilted_orientation_range_deg =
      number(params, "tilted_orientation_range_deg", s.tilted_orientation_range_deg, 0.0, true);
  // The bites follow the fingers unless set: half their depth, and at the support half that
  // (Baxter's 6 cm fingers: 3 and 1.5 cm).
  s.min_bite_m = number(params, "min_bite_m", 0.5 * s.hand.depth_m, 0.0, true);
  s.clearance_m = number(params, "clearance_m", s.clearance_m, 0.0, true);
  s.support_clearance_m = number(params, "support_clearance_m", s.support_clearance_m, 0.0, true);
  s.min_bite_at_support_m = number(params, "min_bite_at_support_m", 0.5 * s.min_bite_m, 0.0, true);
  s.max_view_angle_deg = number(params, "max_view_angle_deg", s.max_view_angle_deg, 0.0, false);
  s.reject_hidden_fingers = params.get<bool>("reject_hidden_fingers", s.reject_hidden_fingers);
  s.occlusion_margin_m = number(params, "occlusion_margin_m", s.occlusion_margin_m, 0.0, true);
  s.point_radius_m = number(params, "point_radius_m", s.point_radius_m, 0.0, false);
  s.keep_all_positions = params.get<bool>("keep_all_positions", s.keep_all_positions);
  s.support_plane = support_mode(params);
  const double support_distance =
      number(params, "support_distance_m", s.support.distance_m, 0.0, false);
  if (support_distance >= 0.1) {
    params.fail("support_distance_m", "parameter 'support_distance_m' must be below 0.1, got " +
                                          std::to_string(support_distance));
  }
  s.support.distance_m = static_cast<float>(support_distance);
  s.threads = integer(params, "threads", 0, 0);
  s.sample_region = box(params, "sample_region");
  return s;
}

ObjectMode object_mode(const Parameters& params) {
  const std::string value = params.get<std::string>("objects", "auto");
  if (value == "auto") return ObjectMode::kAuto;
  if (value == "all") return ObjectMode::kAll;
  params.fail("objects", "parameter 'objects' must be 'auto' or 'all', got '" + value + "'");
}

// A bin's walls as fixtures (`scene.bin`): grown 4 mm into the box, the sensor's depth noise
// on a face seen at a slant, and 1 cm on every other side, so that no wall point joins an object.
constexpr double kBinFixtureInward_m = 0.004;
constexpr double kBinFixtureOutward_m = 0.01;

// Boxes given as [xmin, ymin, zmin, xmax, ymax, zmax] lists.
std::vector<AxisBox> boxes(const Parameters& params, const std::string& key) {
  std::vector<AxisBox> out;
  for (const auto& b : params.get<std::vector<std::vector<double>>>(key, {})) {
    if (b.size() != 6)
      params.fail(key, "each of '" + key + "' must be [xmin, ymin, zmin, xmax, ymax, zmax]");
    out.push_back({Eigen::Vector3d(b[0], b[1], b[2]).cast<float>(),
                   Eigen::Vector3d(b[3], b[4], b[5]).cast<float>()});
  }
  return out;
}

SceneOptions scene_options(const Parameters& params) {
  const Parameters p = params.child("scene");
  SceneOptions o;
  o.max_planes = integer(p, "max_planes", o.max_planes, 1);
  o.max_object_height_m =
      float(number(p, "max_object_height_m", o.max_object_height_m, 0.0, false));
  o.min_object_height_m =
      float(number(p, "min_object_height_m", o.min_object_height_m, 0.0, false));
  o.max_object_size_m = float(number(p, "max_object_size_m", o.max_object_size_m, 0.0, false));
  o.max_gap_m = float(number(p, "max_gap_m", o.max_gap_m, 0.0, true));
  o.max_rest_gap_m = float(number(p, "max_rest_gap_m", o.max_rest_gap_m, 0.0, true));
  o.cluster_tolerance_m =
      float(number(p, "cluster_tolerance_m", o.cluster_tolerance_m, 0.0, false));
  o.min_object_points = std::size_t(integer(p, "min_object_points", int(o.min_object_points), 1));
  if (p.has("up")) o.up = vector3(p, "up", Eigen::Vector3f::UnitZ()).normalized();
  p.get<std::vector<double>>("up", {});  // known either way
  o.max_tilt_deg = float(number(p, "max_tilt_deg", o.max_tilt_deg, 0.0, true));
  o.fixtures = boxes(p, "fixtures");
  const Parameters bin = p.child("bin");  // known either way
  if (p.has("bin")) {
    const std::vector<AxisBox> walls =
        read_bin(bin).fixtures(kBinFixtureInward_m, kBinFixtureOutward_m);
    o.fixtures.insert(o.fixtures.end(), walls.begin(), walls.end());
  }
  p.reject_unknown();
  try {
    o.validate();
  } catch (const Error& error) {
    params.fail("scene", error.message());
  }
  return o;
}

}  // namespace

HandSamplingOptions read_sampler_settings(const Parameters& params) {
  HandSamplingOptions options;
  options.preprocess.voxel_size_m = static_cast<float>(
      number(params, "voxel_size_m", options.preprocess.voxel_size_m, 0.0, true));
  options.preprocess.workspace = box(params, "workspace");
  options.search = search_parameters(params);
  options.default_view_origin_m = vector3(params, "view_origin", Eigen::Vector3f::Zero());
  options.objects = object_mode(params);
  options.scene = scene_options(params);
  options.max_range_m = float(number(params, "max_range_m", 0.0, 0.0, true));
  params.reject_unknown();
  try {
    options.search.validate();
  } catch (const Error& error) {
    params.fail("", error.message());
  }
  return options;
}

}  // namespace antipode::samplers
