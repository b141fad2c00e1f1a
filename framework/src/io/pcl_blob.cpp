#include "pcl_blob.hpp"

#include <cstring>

#include "antipode/core/error.hpp"

namespace antipode::io {
namespace {

struct Coordinate {
  std::size_t offset = 0;
  bool is_double = false;
};

Coordinate find_coordinate(const std::string& path, const pcl::PCLPointCloud2& blob,
                           const std::string& name) {
  for (const auto& field : blob.fields) {
    if (field.name != name) continue;
    const bool is_double = field.datatype == pcl::PCLPointField::FLOAT64;
    if (!is_double && field.datatype != pcl::PCLPointField::FLOAT32) {
      throw Error("field '" + name + "' is not floating point", {path});
    }
    if (field.offset + (is_double ? 8u : 4u) > blob.point_step) {
      throw Error("corrupt cloud data: field '" + name + "' lies outside the point record", {path});
    }
    return {field.offset, is_double};
  }
  throw Error("the cloud has no '" + name + "' field", {path});
}

float read_value(const std::uint8_t* record, const Coordinate& c) {
  if (c.is_double) {
    double value;
    std::memcpy(&value, record + c.offset, sizeof value);
    return static_cast<float>(value);
  }
  float value;
  std::memcpy(&value, record + c.offset, sizeof value);
  return value;
}

}  // namespace

std::vector<Eigen::Vector3f> coordinates_of(const std::string& path,
                                            const pcl::PCLPointCloud2& blob) {
  const Coordinate x = find_coordinate(path, blob, "x");
  const Coordinate y = find_coordinate(path, blob, "y");
  const Coordinate z = find_coordinate(path, blob, "z");
  const std::size_t width = blob.width;
  const std::size_t height = blob.height;
  const std::size_t needed_row = width * blob.point_step;
  if (blob.row_step < needed_row || blob.data.size() < height * blob.row_step) {
    throw Error("corrupt cloud data: " + std::to_string(blob.data.size()) + " bytes for " +
                    std::to_string(width * height) + " points",
                {path});
  }
  std::vector<Eigen::Vector3f> points;
  points.reserve(width * height);
  for (std::size_t row = 0; row < height; ++row) {
    const std::uint8_t* record = blob.data.data() + row * blob.row_step;
    for (std::size_t col = 0; col < width; ++col, record += blob.point_step) {
      points.emplace_back(read_value(record, x), read_value(record, y), read_value(record, z));
    }
  }
  return points;
}

}  // namespace antipode::io
