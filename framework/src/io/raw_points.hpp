#pragma once
// Internal to the io area: what a format reader hands back to load_cloud().

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace antipode::io {

/// Every point a file declares, finite or not, and the sensor pose it records (if any): its
/// origin and rotation in the file's frame (a PCD's VIEWPOINT).
struct RawPoints {
  std::vector<Eigen::Vector3f> points_m;
  /// A binary PCD's `view` field (unsigned, 4 bytes: save_cloud_pcd's view masks), one per
  /// point, when the file has one; empty otherwise.
  std::vector<std::uint32_t> view_masks;
  std::optional<Eigen::Vector3f> origin_m;
  Eigen::Quaternionf rotation = Eigen::Quaternionf::Identity();
};

/// The whole content of `path`; throws Error when the file cannot be opened or read.
std::string read_file_bytes(const std::string& path);

/// Parses a PCD file whose content is `bytes`. Throws Error naming `path`.
RawPoints read_pcd(const std::string& path, const std::string& bytes);

/// Parses a PLY file whose content is `bytes`. Throws Error naming `path`.
RawPoints read_ply(const std::string& path, const std::string& bytes);

}  // namespace antipode::io
