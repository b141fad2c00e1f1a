#pragma once
/// @file
/// Writing point clouds to PCD files.

#include <string>

#include "antipode/core/cloud.hpp"

namespace antipode {

/// Writes `cloud` to `path` as a binary PCD file (version 0.7, unorganised): the fields x, y,
/// z (float32, metres, in the cloud's frame) and, when the cloud has view masks, `view` (uint32:
/// bit k set when view k saw the point). load_cloud() reads it back (the extra field ignored);
/// so does PCL. Normals and view origins are not written.
///
/// All or nothing (write_file_atomically): a failed write leaves no file and throws
/// antipode::Error naming `path`. Thread-safe for different paths.
void save_cloud_pcd(const Cloud& cloud, const std::string& path);

}  // namespace antipode
