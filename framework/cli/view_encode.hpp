#pragma once
// `antipode view`: the page's compact encodings of clouds and hands (docs/viewer.md, "What is in
// the page"). Numbers go in as base64 of little-endian float32, so a page of 300,000 points and
// 5,000 hands stays a few megabytes and the browser decodes it without parsing JSON numbers.

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "antipode/core/cloud.hpp"

namespace antipode::cli {

/// The index of `name` in `names` (the page's lists of reasons, labels and statuses), which
/// it is appended to when new; `known` maps the names already there to their indices.
int name_index(const std::string& name, nlohmann::ordered_json& names,
               std::map<std::string, int>& known);

/// Base64 (RFC 4648, no line breaks) of `size` bytes.
std::string base64(const void* bytes, std::size_t size);

/// {"count", "points": base64 float32 x, y, z per point, metres} and, when the points were
/// not all seen by the same views, "views": base64 uint32 per point, its view mask (bit k:
/// view k saw it).
nlohmann::ordered_json cloud_json(const Cloud& cloud);

/// The hands of a grasps file (`antipode detect --out`, WriteGrasps) as columns: "count";
/// base64 float32 "position_m" (3 per hand), "quaternion_xyzw" (4), "width_m", "open_width_m"
/// and "score"; integer lists "rank" (0 = not selected) and "object" (-1 = none); and "label"
/// and "rejection" as indices into "labels" and "reasons" (-1 = none: accepted). Throws
/// antipode::Error naming `path` and the hand for a file that is not a grasps file.
nlohmann::ordered_json hand_table(const nlohmann::ordered_json& grasps, const std::string& path);

}  // namespace antipode::cli
