#pragma once
/// @file
/// The part of a multi-view cloud that some of its views saw.

#include <cstdint>
#include <vector>

#include "antipode/core/cloud.hpp"

namespace antipode {

/// The points of `cloud` seen by any of `views`, in their original order, renumbered as views
/// 0, 1, ... in the order `views` lists them (origins and masks follow). A cloud without view
/// origins is one view, view 0, and stays without origins and masks. Normals and the frame
/// are kept. When `new_index` is given it receives, per point of `cloud`, its index in the
/// result or -1. Throws antipode::Error for an empty list, a view listed twice or a view the
/// cloud does not have.
Cloud points_of_views(const Cloud& cloud, const std::vector<int>& views,
                      std::vector<std::int32_t>* new_index = nullptr);

}  // namespace antipode
