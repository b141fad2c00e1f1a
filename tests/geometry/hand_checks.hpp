#pragma once
// Checks every hand of a search result against the exact box model and the result contract.

#include "antipode/core/cloud.hpp"
#include "antipode/geometry/hand_search.hpp"

namespace antipode::testing {

/// Non-fatal GoogleTest failures for any hand that collides with `cloud`, has an empty or
/// wrong closing-point list, a non-orthonormal or left-handed rotation, a wrong frame, a
/// sample index outside the cloud, or a width beyond the aperture; and for stats that do
/// not add up.
void expect_valid_hands(const Cloud& cloud, const HandSearchResult& result,
                        const HandSearchParameters& parameters);

/// True when both results hold the same hands (poses, closing points, widths) in the same
/// order and the same sample points.
bool same_hands(const HandSearchResult& a, const HandSearchResult& b);

}  // namespace antipode::testing
