#pragma once
// Where along the fingers each finger first meets the object.
//
// A finger closing on an object first touches the object's points farthest out towards it
// along the closing direction: its contact patch. Where that patch lies along the fingers
// tells which way the squeeze pushes. An object that is widest above the fingertips (a box's
// face, a ball held at or below its equator) meets each finger along its length, on faces
// that turn the squeeze back into the hand. An object still widening at the fingertips - a
// ball or a lying ellipsoid held above its equator, a tilted bottle's shoulder - meets them
// only there, on a surface that faces the palm: the squeeze pushes it out past the tips.
// The patches tell them apart: each finger's patch is the closing-region points within
// `patch_m` of its first contact, and its start the patch point nearest the palm along the
// approach. When either patch starts in the last `fingertip_margin_m` of the fingers, the
// grasp holds the object above its widest part.
//
// Its effect on the clear-the-box benches, with and without it: docs/results.md.

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"

namespace antipode::selectors {

/// The start of the later of the two fingers' contact patches (above): the largest, over the
/// two fingers, of the smallest approach coordinate (m from the palm face) of the
/// closing-region points within `patch_m` of that finger's first contact. A hand without
/// closing points (made by hand, or read from a grasps file) gives 0.
double contact_start_m(const Hand& hand, const Cloud& cloud, double patch_m);

}  // namespace antipode::selectors
