#pragma once
// How steeply a grasp closes relative to the support. A parallel gripper holding an object
// that rests on a support closes best along the support: tilted, the lower finger has to
// find a surface facing down, which sits low against the support where the finger cannot
// reach (it stays above the support) and which no sensor above the table sees, and the
// squeeze then presses the object into the support or levers it out of the fingers. In the
// isolation bench the share of held objects falls from about 95% for closings within 15
// degrees of the support to about a quarter beyond 30 degrees (docs/selection.md).

#include <Eigen/Core>

#include "antipode/core/hand.hpp"

namespace antipode::selectors {

/// The angle in [0, pi/2] between the hand's closing direction and the plane normal to `up`
/// (unit): 0 when the fingers close along the support, pi/2 when they close vertically.
double closing_tilt_rad(const Hand& hand, const Eigen::Vector3d& up);

/// The tilt criterion: zero up to `free_rad`, (tilt - free)^2 (rad^2) beyond.
double tilt_penalty(double tilt_rad, double free_rad);

}  // namespace antipode::selectors
