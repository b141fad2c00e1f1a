#pragma once
// The width the fingers will meet. A hand's width_m is the full extent of its closing-region
// points along the closing direction, which a few stray points decide: at a thin feature's
// silhouette the depth error grows steeply with the incidence angle (docs/cell.md, sensor
// model), so a 2.7 cm bottle neck seen from two sides spreads to 5-6 cm in a noisy cloud and
// looks like a safe grasp for a gripper that closes no narrower than 3 cm. Trimming the
// extremes along the closing direction gives the width of the bulk of the surface instead,
// scaled back by 1 / (1 - 2 trim) to the extent it implies for evenly spread points: on a
// clean cloud it is the full extent, so objects just wider than the closed gripper (which
// the trimmed bulk alone would put under it, 10% narrow) stay graspable.

#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"

namespace antipode::selectors {

/// The extent along `hand.closing()` of the hand's closing-region points (indices into
/// `cloud`) between the `trim` and 1 - `trim` quantiles (trim in [0, 0.5); 0 gives the
/// full extent), divided by 1 - 2 trim. A hand without closing points (made by hand, or
/// read from a grasps file) gives its `width_m`. `scratch` is working space, reused across
/// calls (nothing is allocated once it has grown to the largest closing region).
double held_width_m(const Hand& hand, const Cloud& cloud, double trim,
                    std::vector<float>& scratch);

}  // namespace antipode::selectors
