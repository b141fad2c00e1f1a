#pragma once
// Can the hand get to its pose? Its body and its straight way in from the stand-off pose,
// against the support plane, the observed points and the space no sensor saw.

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/hand_geometry.hpp"
#include "antipode/geometry/occlusion.hpp"
#include "antipode/geometry/support_plane.hpp"

namespace antipode::selectors {

/// True when every corner of the hand's body (fingers and palm, see hand_body.hpp) stays at
/// least `clearance_m` above `support`, at the hand's pose and at every pose on its straight
/// way in from `standoff_m` back along the approach. The body's extreme points are corners
/// of its bounding box, so eight corners of the swept box decide exactly.
bool clears_support(const Hand& hand, const HandGeometry& geometry, const SupportPlane& support,
                    double standoff_m, double clearance_m);

/// True when no point of `cloud` lies in the hand's fingers or palm at its pose, nor in the
/// space the palm sweeps on its straight way in from `standoff_m` back (a point less than a
/// millimetre in front of the palm face, where the search leaves its clearance, is not
/// counted). The points between the fingers are the object and do not count. Visits every
/// point: call it for the few grasps about to be returned.
bool approach_is_free(const Hand& hand, const HandGeometry& geometry, const Cloud& cloud,
                      double standoff_m);

/// True when the hand's straight way in from `standoff_m` back passes only through space a
/// sensor saw: no probe on the centre lines of the palm and of both fingers, every
/// centimetre behind the grasp's palm face, lies more than `margin_m` behind an observed
/// surface in every view (OcclusionMap::hidden). Observed points mark only surfaces: a
/// way in that starts inside a solid part (under the cross bar of a T, say) meets no point,
/// but its probes lie hidden behind the part's top. The fingers at the grasp itself are the
/// sampler's to check (sampling.md, "fingers in observed space").
bool way_in_is_seen(const Hand& hand, const HandGeometry& geometry, const OcclusionMap& occlusion,
                    double standoff_m, float margin_m);

}  // namespace antipode::selectors
