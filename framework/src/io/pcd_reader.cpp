// PCD files: the header is parsed and checked here, ascii data is parsed here, and binary or
// binary_compressed data is handed to PCL only once its size matches the header (PCL
// crashes on some malformed headers and allocates whatever POINTS declares before noticing
// a short file).
#include <pcl/io/pcd_io.h>

#include "antipode/core/error.hpp"
#include "pcd_ascii.hpp"
#include "pcd_header.hpp"
#include "pcl_blob.hpp"
#include "raw_points.hpp"

namespace antipode::io {
namespace {

std::vector<Eigen::Vector3f> read_binary_with_pcl(const std::string& path,
                                                  const PcdHeader& header) {
  silence_pcl_console();
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  pcl::PCDReader reader;
  if (reader.read(path, blob, origin, orientation, version, 0) < 0) {
    throw Error(std::string("corrupt PCD file: its ") +
                    (header.data == PcdData::kBinary ? "binary" : "compressed") +
                    " data cannot be decoded",
                {path});
  }
  if (static_cast<std::uint64_t>(blob.width) * blob.height != header.points) {
    throw Error("corrupt PCD file: the data decodes to " +
                    std::to_string(static_cast<std::uint64_t>(blob.width) * blob.height) +
                    " points, the header declares " + std::to_string(header.points),
                {path});
  }
  return coordinates_of(path, blob);
}

}  // namespace

RawPoints read_pcd(const std::string& path, const std::string& bytes) {
  const PcdHeader header = parse_pcd_header(path, bytes);
  check_pcd_data_size(path, bytes, header);
  RawPoints raw;
  raw.origin_m = header.viewpoint_m;
  if (header.points == 0) return raw;
  raw.points_m = header.data == PcdData::kAscii ? read_pcd_ascii_points(path, bytes, header)
                                                : read_binary_with_pcl(path, header);
  return raw;
}

}  // namespace antipode::io
