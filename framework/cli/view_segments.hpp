#pragma once
// `antipode view`: the support and the object segments of a cloud as antipode's scene stage
// finds them (find_scene_layout with its default options, on the cloud thinned to the
// sampler's 3 mm voxels), for the page to colour the cloud by segment and draw the support.

#include <nlohmann/json.hpp>

#include "antipode/core/cloud.hpp"

namespace antipode::cli {

/// The segments of `cloud` for the points of `shown` (the cloud the page draws: `cloud` itself,
/// or `cloud` thinned): {"segments": base64 int16 per point of `shown` (its object's id, -1
/// for the support, -2 for anything else), "objects": how many, "support": the support as
/// four corners (x, y, z each, metres): the rectangle in its plane bounding the points of
/// `cloud` within 1 cm of it, or null when there is none}. A point takes the label of its
/// 3 mm voxel.
nlohmann::ordered_json segments_json(const Cloud& cloud, const Cloud& shown);

/// The page's cloud of a scene: `cloud` thinned to one point per voxel of `voxel_m` (0: all
/// points) as cloud_json() encodes it, with its "segments" and "objects" (above), and the
/// support's corners set as `scene["support"]`.
void add_cloud(const Cloud& cloud, double voxel_m, nlohmann::ordered_json& scene);

}  // namespace antipode::cli
