#pragma once
/// @file
/// Scene understanding before sampling: which surface the objects stand on, and the objects
/// on it as segments. A user's own cloud shows a room - a table with objects, walls and
/// furniture behind, the floor - and grasps belong on the objects, not on the room's edges.
///
/// The support is the plane with the most object points standing on it, which need not be
/// the largest plane in view (a floor or a wall can hold more points than the table):
///  1. Candidate planes are found one after another by RANSAC, each from the points the
///     ones before did not take (up to `max_planes`, each with at least `min_plane_points`
///     inliers), refitted by least squares and oriented towards the sensors.
///     A candidate must be a surface seen face-on (most inliers' local normals along its
///     normal) with little behind it within its extent (a plane through an object is not).
///  2. For each candidate, the points above it (more than the support distance, at most
///     `max_object_height_m`) whose foot lies within the convex hull of its inliers are
///     split into Euclidean clusters (`cluster_tolerance_m`).
///  3. A cluster is an object standing on the candidate when it has at least
///     `min_object_points` points, reaches down to within `max_gap_m` of the plane, rises
///     at least `min_object_height_m` above it, stops below the height limit (a wall or a
///     shelf running through the slab does not) and is at most `max_object_size_m` across
///     along the plane. A cluster lower than `min_object_height_m` is taken for a stretch
///     of the support itself: a far, noisy or bent part of a table yields flat patches a
///     little beyond the inlier distance.
///     A cluster that passes every test but reaching down is an object resting on others
///     when a chain of such clusters, each within `max_rest_gap_m` of the next, joins it to
///     a standing one: the upper layer of a pile, which hides its own lower part (and the
///     objects under it) from the sensors, so that its lowest visible point can be far above
///     the plane. It does not count towards the support's choice (step 4).
///  4. The support is the candidate with the most object points (ties: more inliers). With
///     `up` given (the direction against gravity in the cloud's frame), only candidates whose
///     normal lies within `max_tilt_deg` of it count; without, "up" is each plane's normal
///     towards the sensors.
/// Points inside a `fixtures` box (a bin's walls) are never objects; they stay in the cloud
/// as obstacles. No candidate with an object: no support, and the caller uses the whole
/// cloud (as the hand search does without this stage).
///
/// Units: metres; frame: the cloud's. Deterministic for a given `random`; single-threaded.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"
#include "antipode/geometry/axis_box.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode {

struct SceneOptions {
  int max_planes = 5;
  std::size_t min_plane_points = 200;
  float plane_distance_m = 0.01f;  ///< inlier distance of a plane (noise plus voxel size)
  int plane_iterations = 300;      ///< RANSAC hypotheses per candidate plane
  float max_object_height_m = 0.35f;
  /// The least height of an object's top above the plane: a marker pen lying down (1.9 cm)
  /// is an object, a 1.2 cm rise of the table's far end is not.
  float min_object_height_m = 0.015f;
  float max_object_size_m = 0.5f;
  float max_gap_m = 0.03f;  ///< how far above the plane an object's lowest point may be
  /// How close a cluster that does not reach the plane must come to an object to rest on it
  /// (step 3); 0: only clusters that reach the plane are objects.
  float max_rest_gap_m = 0.015f;
  float cluster_tolerance_m = 0.006f;  ///< neighbours on a 3 mm voxel grid, and a little noise
  std::size_t min_object_points = 30;
  std::optional<Eigen::Vector3f> up;  ///< against gravity, in the cloud's frame (unit)
  float max_tilt_deg = 30.0f;
  std::vector<AxisBox> fixtures;

  /// Throws antipode::Error naming the first invalid field.
  void validate() const;
};

/// One object standing on the support, or resting on objects that do: a segment of the cloud.
struct SceneObject {
  std::int32_t id = 0;               ///< 0, 1, ... in the order of their first point
  std::vector<std::int32_t> points;  ///< indices into the cloud, increasing
  Eigen::Vector3f centroid_m = Eigen::Vector3f::Zero();
  Eigen::Vector3f min_m = Eigen::Vector3f::Zero();  ///< axis-aligned bounds in the cloud's frame
  Eigen::Vector3f max_m = Eigen::Vector3f::Zero();
  float height_m = 0.0f;  ///< highest point above the support
};

struct SceneLayout {
  std::optional<SupportPlane> support;  ///< unset: no support surface was found
  std::vector<SceneObject> objects;     ///< empty without a support
  /// Per cloud point: the id of its object, or -1.
  std::vector<std::int32_t> object_of_point;
  std::size_t planes = 0;  ///< candidate planes examined

  /// describe_scene(support, objects).
  std::string summary() const;
};

/// One line: "support plane 0.000 x + 0.000 y + 1.000 z + 0.295 = 0 (51234 points), 2
/// objects: #0: 812 points, 6.1 x 5.8 x 9.2 cm at (0.700, -0.100, -0.250); #1: ..." or
/// "no support surface: the whole cloud is used".
std::string describe_scene(const std::optional<SupportPlane>& support,
                           const std::vector<SceneObject>& objects);

/// The same line with each object's size measured along the support, whatever the cloud's
/// axes: "#0: 2088 points, 11.8 x 8.6 cm on the support, 10.7 cm tall at (...)" - the
/// sides of the smallest rectangle around its footprint, then its height.
/// `points` is the cloud the objects' indices refer to.
std::string describe_scene(const std::optional<SupportPlane>& support,
                           const std::vector<SceneObject>& objects,
                           const std::vector<Eigen::Vector3f>& points);

/// Finds the support and the objects on it in `cloud` (preprocessed: finite points, voxels),
/// seen from `toward_sensor` (a point on the sensors' side). Throws antipode::Error for
/// invalid options.
SceneLayout find_scene_layout(const Cloud& cloud, const Eigen::Vector3f& toward_sensor,
                              const SceneOptions& options, RandomStream random);

}  // namespace antipode
