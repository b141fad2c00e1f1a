#pragma once
// How far a grasp is from the object's centre of mass. A parallel gripper resists a torque
// about its closing axis only by the friction within its small contact patches: an object
// lifted far from its centre of mass turns about that axis and slips out (a bottle lifted
// by its end). The views show roughly where the mass is.

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/geometry/scene_layout.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode::selectors {

/// The points of a cloud that belong to objects: more than `above_m` above `support` (every
/// point when there is no support).
std::vector<Eigen::Vector3f> object_points(const Cloud& cloud,
                                           const std::optional<SupportPlane>& support,
                                           float above_m);

/// The centroid of the points within `radius_m` of `centre` (the visible part of the object
/// a grasp there holds, in an isolated scene), or nothing when there are none.
std::optional<Eigen::Vector3d> centroid_near(const std::vector<Eigen::Vector3f>& points,
                                             const Eigen::Vector3d& centre, double radius_m);

/// The centroid of the points of `object` (indices into `cloud`) within `radius_m` of
/// `centre`: in a segmented scene, the visible part of the object a grasp there holds
/// without its neighbours. Nothing when there are none.
std::optional<Eigen::Vector3d> object_centroid_near(const Cloud& cloud, const SceneObject& object,
                                                    const Eigen::Vector3d& centre, double radius_m);

/// The lever arm of gravity about the hand's closing axis through its grasp centre, for a
/// mass at `centroid` and "up" along `up` (unit): |(centroid - centre) . (up x closing)|.
/// Zero when the fingers close along the vertical (gravity then has no torque about them).
double torque_arm_m(const Hand& hand, const HandGeometry& geometry, const Eigen::Vector3d& centroid,
                    const Eigen::Vector3d& up);

}  // namespace antipode::selectors
