#pragma once
/// @file
/// Reading point clouds from PCD and PLY files.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

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

/// The view masks a binary PCD file holds in a `view` field (unsigned, 4 bytes, as
/// save_cloud_pcd writes them: bit k set when view k saw the point), one for each point
/// load_cloud() keeps, in the same order; empty when the file has no such field (a PLY file,
/// an ascii PCD, a PCD of other fields). Throws as load_cloud() does.
std::vector<std::uint32_t> load_view_masks(const std::string& path);

/// As load_cloud(), with the points and the view origin moved from the file's frame into
/// `options.frame`, in which the file's frame has the pose `X_FrameFile` (for a depth
/// camera's cloud, whose points are in the camera's frame: the camera's extrinsics in a
/// robot's base frame). A point p of the file lands at X_FrameFile * p; the view origin (a
/// PCD's VIEWPOINT position, else the file frame's origin) moves with it.
///
/// A PCD's VIEWPOINT rotation is not applied: PCL defines it as the sensor's orientation in
/// the file's frame, but files from depth cameras often carry one that contradicts their
/// points (the shared table_mug.pcd says the sensor faces away from every point). When the
/// rotation is not the identity, `note` (if given) receives one line saying so; otherwise it
/// is left empty. Throws as load_cloud() does.
Cloud load_cloud_into(const std::string& path, const Eigen::Isometry3d& X_FrameFile,
                      const LoadCloudOptions& options = {}, std::string* note = nullptr);

}  // namespace antipode
