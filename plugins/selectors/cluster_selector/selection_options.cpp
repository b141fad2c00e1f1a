#include "selection_options.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_file.hpp"
#include "collision_options.hpp"

namespace antipode::selectors {
namespace {

// A whole number in [lo, hi] (a count or an id: 1.5 is an error, not 1).
double whole(const Parameters& params, const std::string& key, double fallback, double lo,
             double hi) {
  const double value = params.number_in(key, fallback, lo, hi);
  if (value != std::floor(value))
    params.fail(key,
                "parameter '" + key + "' must be a whole number, got " + std::to_string(value));
  return value;
}

// `bin:` (antipode/geometry/bin.hpp), when given.
std::optional<Bin> optional_bin(const Parameters& params) {
  const Parameters p = params.child("bin");  // known either way
  if (!params.has("bin")) return std::nullopt;
  return antipode::read_bin(p);
}

}  // namespace

SelectionOptions read_selection_options(const Parameters& params) {
  SelectionOptions o;
  o.standoff_m = params.number_in("standoff_m", o.standoff_m, 0.0, 0.5);
  o.clearance_m = params.number_in("clearance_m", o.clearance_m, 0.0, 0.1);
  if (params.has("support_z_m")) o.support_z_m = params.number_in("support_z_m", 0.0, -1e3, 1e3);
  params.get<double>("support_z_m", 0.0);  // known either way
  o.bin = optional_bin(params);
  o.cluster_distance_m = params.number_in("cluster_distance_m", o.cluster_distance_m, 0.0, 0.5);
  o.cluster_angle_deg = params.number_in("cluster_angle_deg", o.cluster_angle_deg, 0.0, 180.0);
  o.min_cluster_size =
      std::size_t(params.number_in("min_cluster_size", double(o.min_cluster_size), 1, 1e6));
  o.tilt_free_deg = params.number_in("tilt_free_deg", o.tilt_free_deg, 0.0, 90.0);
  o.tilt_tolerance_rad2 = params.number_in("tilt_tolerance_rad2", o.tilt_tolerance_rad2, 0.0, 10.0);
  o.occlusion_margin_m = params.number_in("occlusion_margin_m", o.occlusion_margin_m, 0.0, 0.1);
  o.point_radius_m = params.number_in("point_radius_m", o.point_radius_m, 0.0005, 0.02);
  o.unseen_is_free = params.get<bool>("unseen_is_free", o.unseen_is_free);
  o.aperture_margin_m = params.number_in("aperture_margin_m", o.aperture_margin_m, 0.0, 0.1);
  o.width_trim = params.number_in("width_trim", o.width_trim, 0.0, 0.45);
  o.squeeze_turn_deg = params.number_in("squeeze_turn_deg", o.squeeze_turn_deg, 0.0, 90.0);
  o.min_finger_cover = params.number_in("min_finger_cover", o.min_finger_cover, 0.0, 1.0);
  o.fingertip_margin_m = params.number_in("fingertip_margin_m", o.fingertip_margin_m, 0.0, 0.5);
  o.fingertip_last_resort = params.get<bool>("fingertip_last_resort", o.fingertip_last_resort);
  o.grasps_per_object =
      std::size_t(whole(params, "grasps_per_object", double(o.grasps_per_object), 0, 1e6));
  o.object = std::int32_t(whole(params, "object", double(o.object), -1, 1e6));
  const auto near = params.get<std::vector<double>>("near_m", {});
  if (params.has("near_m")) {
    if (near.size() != 3 || !std::isfinite(near[0] + near[1] + near[2]))
      params.fail("near_m", "'near_m' must be a point [x, y, z]");
    if (o.object >= 0) params.fail("near_m", "give either 'object' or 'near_m', not both");
    o.near_m = Eigen::Vector3d(near[0], near[1], near[2]);
  }
  o.balance_free_m = params.number_in("balance_free_m", o.balance_free_m, 0.0, 1.0);
  o.max_torque_arm_m = params.number_in("max_torque_arm_m", o.max_torque_arm_m, 0.0, 1.0);
  o.object_radius_m = params.number_in("object_radius_m", o.object_radius_m, 0.01, 2.0);
  o.penalty_tolerance_m2 =
      params.number_in("penalty_tolerance_m2", o.penalty_tolerance_m2, 0.0, 1.0);
  o.score_first_tolerance =
      params.number_in("score_first_tolerance", o.score_first_tolerance, 0.0, 1e6);
  o.max_grasps = std::size_t(params.number_in("max_grasps", double(o.max_grasps), 1, 1e6));
  o.threads = int(whole(params, "threads", o.threads, 0, 256));
  if (params.has("robot")) {
    const RobotFile robot = robot_file_parameter(params, "robot");
    o.arm.robot_file = robot.urdf_path;
    o.arm.arm_tip = robot.arm_tip;
    o.arm.points_unchecked = robot.points_unchecked;
  }
  o.arm.points_resolution_m =
      params.number_in("points_resolution_m", o.arm.points_resolution_m, 0.001, 0.1);
  o.arm.ik_solutions = int(params.number_in("ik_solutions", o.arm.ik_solutions, 1, 100));
  // nearest_pregrasp would give the selector the same answers as first_free at more cost:
  // it chooses among pre-grasps, and the selector keeps only whether there is one.
  const std::string search = params.get<std::string>("reach_search", "first_free");
  if (search != "first_free" && search != "exhaustive")
    params.fail("reach_search", "'reach_search' must be first_free or exhaustive, got '" + search +
                                    "'" + did_you_mean(search, {"first_free", "exhaustive"}));
  o.arm.search = collision::reach_search(search);
  const std::string kinematics = params.get<std::string>("ik_kinematics", "one_pass");
  if (kinematics != "one_pass" && kinematics != "kdl")
    params.fail("ik_kinematics", "'ik_kinematics' must be one_pass or kdl, got '" + kinematics +
                                     "'" + did_you_mean(kinematics, {"one_pass", "kdl"}));
  o.arm.ik_solver =
      kinematics == "kdl" ? IkSolver::kDampedLeastSquaresKdl : IkSolver::kDampedLeastSquares;
  o.arm.collision = collision::collision_options(params, o.arm.collision.mode);
  params.reject_unknown();
  return o;
}

}  // namespace antipode::selectors
