#pragma once
// The width the fingers will meet.
//
// Stray points. A hand's width_m is the full extent of its closing-region points along the
// closing direction, which a few stray points decide: at a thin feature's silhouette the
// depth error grows steeply with the incidence angle (docs/cell.md, sensor model), so a
// 2.7 cm bottle neck seen from two sides spreads to 5-6 cm in a noisy cloud and looks like
// a safe grasp for a gripper that closes no narrower than 3 cm. Trimming the extremes along
// the closing direction gives the width of the bulk of the surface instead, scaled back by
// 1 / (1 - 2 trim) to the extent it implies for evenly spread points, and never more than
// the full extent: on a clean cloud it is the full extent, so objects just wider than the
// closed gripper (which the trimmed bulk alone would put under it, 10% narrow) stay
// graspable, and a 2.6 cm plate, whose points lie on its two faces, stays 2.6 cm wide
// (scaled back alone, it would pass for 2.9 cm).
//
// The squeeze. Parallel jaws closing on a part turn it until its width between them is at a
// local minimum of its width function (Goldberg, "Orienting polygonal parts without
// sensors", 1993): a 2.6 cm plate leaning 16 degrees across the closing direction is 3.3 cm
// wide along it where the fingers first touch it, turns as they close, and ends 2.6 cm wide
// - thinner than the closed gripper. The width held is therefore the width at the local
// minimum reached by turning the closing direction about the approach axis or the hand
// axis, from the hand's own direction downhill, within a bound (the turns the part's
// friction allows; a partial view's missing back also narrows as it turns).

#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"

namespace antipode::selectors {

/// The extent along `direction` of the hand's closing-region points (indices into `cloud`)
/// between the `trim` and 1 - `trim` quantiles (trim in [0, 0.5); 0 gives the full extent),
/// divided by 1 - 2 trim, at most the full extent. The hand must have closing points. `scratch` is
/// working space, reused across calls (nothing is allocated once it has grown to the largest
/// region).
double trimmed_extent_m(const Hand& hand, const Cloud& cloud, const Eigen::Vector3f& direction,
                        double trim, std::vector<float>& scratch);

/// The width the hand holds after the squeeze (above): the trimmed extent along the closing
/// direction turned about the approach axis and the hand axis in steps of 2 degrees,
/// steepest descent from the hand's own direction while a step shrinks it by more than
/// 0.5 mm, each turn at most `max_turn_deg` (0: no turn). A hand without closing points (made by
/// hand, or read from a grasps file) gives its `width_m`.
double held_width_m(const Hand& hand, const Cloud& cloud, double trim, double max_turn_deg,
                    std::vector<float>& scratch);

}  // namespace antipode::selectors
