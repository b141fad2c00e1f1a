#pragma once
// How much of the fingers' height the object fills.
//
// Each finger is height_m tall along the hand axis (z), and the closing region is as tall.
// A hand whose closing region only clips an object - the fingers pass over a can's rim, a
// mug's upper edge or a box's top corner - still has points between its fingers, and the
// classifier may score it high; but the fingers meet the object with one edge of their pads,
// on a surface curving away from them, and the object rolls or slides out: it is pushed
// down out of the fingers, or the fingers close above it. The points show it: along the hand
// axis they fill only a band at one side of the closing region instead of all of it.
//
// Its effect on the clear-the-box benches, with and without it: docs/results.md.

#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"

namespace antipode::selectors {

/// The share of the fingers' height (`geometry.height_m`) that the hand's closing-region
/// points span along the hand axis, trimmed as the width is (`trimmed_extent_m` with `trim`),
/// in [0, 1]. A hand without closing points (made by hand, or read from a grasps file) gives
/// 1: nothing says it is short. `scratch` is working space, reused across calls.
double finger_cover(const Hand& hand, const Cloud& cloud, const HandGeometry& geometry, double trim,
                    std::vector<float>& scratch);

}  // namespace antipode::selectors
