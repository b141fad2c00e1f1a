#pragma once
// Internal to the io area: the header of a PCD file (format version 0.7 and earlier).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace antipode::io {

struct PcdField {
  std::string name;
  std::size_t size = 4;  ///< bytes per value: 1, 2, 4 or 8
  char type = 'F';       ///< 'F' float, 'I' signed, 'U' unsigned
  std::size_t count = 1;
  std::size_t offset = 0;  ///< byte offset within a binary point record
  std::size_t column = 0;  ///< index of its first value within an ascii line
};

enum class PcdData { kAscii, kBinary, kBinaryCompressed };

struct PcdHeader {
  std::vector<PcdField> fields;
  std::uint64_t width = 0;
  std::uint64_t height = 1;
  std::uint64_t points = 0;
  /// VIEWPOINT: the sensor's pose in the cloud's frame, as PCL defines it.
  std::optional<Eigen::Vector3f> viewpoint_m;
  Eigen::Quaternionf viewpoint_rotation = Eigen::Quaternionf::Identity();
  PcdData data = PcdData::kAscii;
  std::size_t data_offset = 0;  ///< byte offset of the first data byte in the file
  int data_line = 0;            ///< 1-based line number of the first data line
  std::size_t point_step = 0;   ///< bytes per point record (sum of size * count)
  std::size_t values_per_point = 0;

  /// The field called `name`, or nullptr.
  const PcdField* field(const std::string& name) const;
};

/// Parses and checks the header at the start of `bytes` (fields consistent, x y z present
/// as floating point, WIDTH * HEIGHT == POINTS, DATA known). Throws Error located at the
/// offending line of `path`.
PcdHeader parse_pcd_header(const std::string& path, const std::string& bytes);

/// Throws Error when the data after the header is too short for the points the header
/// declares, or (binary_compressed) when its size fields disagree with the header.
void check_pcd_data_size(const std::string& path, const std::string& bytes,
                         const PcdHeader& header);

}  // namespace antipode::io
