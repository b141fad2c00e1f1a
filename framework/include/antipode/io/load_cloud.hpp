#pragma once
/// @file
/// Reading point clouds from PCD and PLY files.

#include <optional>
#include <string>

#include <Eigen/Core>

#include "antipode/core/cloud.hpp"

namespace antipode {

/// How load_cloud() turns a file into a Cloud.
struct LoadCloudOptions {
  /// Sensor origin of the file's single view, in the file's frame. When unset, a PCD's
  /// VIEWPOINT translation is used; a PCD without VIEWPOINT and a PLY file give (0, 0, 0),
  /// which is where a depth sensor's own frame puts it.
  std::optional<Eigen::Vector3f> view_origin_m;
  /// The name given to the cloud's frame (`Cloud::frame`).
  std::string frame = "sensor";
};

/// Reads the x, y, z coordinates of every point of a PCD file (DATA ascii, binary or
/// binary_compressed; organised or not; fields x, y, z of type F with size 4 or 8, any other
/// fields ignored) or a PLY file (ascii or binary; the `vertex` element's x, y, z).
///
/// The returned cloud has one view (view 0 at the origin described in LoadCloudOptions), a
/// view mask of 1 for every point, no normals, and only the points whose three coordinates
/// are finite (NaN or infinite points, e.g. the holes of an organised cloud, are dropped).
///
/// Throws antipode::Error with a one-line message naming the file for: a missing or
/// unreadable file, an unknown extension (neither .pcd nor .ply), a malformed header (with
/// its line), data shorter than the header declares (truncated file), corrupt data, a file
/// without x, y, z fields, a cloud that declares no point, and a cloud without a finite
/// point. The file is checked against its header before its data is read, so no input makes
/// the process crash or allocate more than the file's size suggests.
///
/// Thread-safe: concurrent calls may read different (or the same) files.
Cloud load_cloud(const std::string& path, const LoadCloudOptions& options = {});

}  // namespace antipode
