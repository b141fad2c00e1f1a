#pragma once
// Internal to the io area: what a format reader hands back to load_cloud().

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace antipode::io {

/// Every point a file declares, finite or not, and the view origin it records (if any).
struct RawPoints {
  std::vector<Eigen::Vector3f> points_m;
  std::optional<Eigen::Vector3f> origin_m;
};

/// The whole content of `path`; throws Error when the file cannot be opened or read.
std::string read_file_bytes(const std::string& path);

/// Parses a PCD file whose content is `bytes`. Throws Error naming `path`.
RawPoints read_pcd(const std::string& path, const std::string& bytes);

/// Parses a PLY file whose content is `bytes`. Throws Error naming `path`.
RawPoints read_ply(const std::string& path, const std::string& bytes);

}  // namespace antipode::io
