// PCD files: the header is parsed and checked here, and the data decoded here in every
// encoding, once its size matches the header. PCL's reader is not used: it parses the header
// again, its own way, and a header that this parser accepts can make PCL's allocate
// terabytes or crash (found by fuzzing: tests/fuzz/corpus/cloud). Compressed data is
// decoded by liblzf (the LZF format PCL writes), on a buffer whose sizes are checked first.
#include <cstdint>
#include <cstring>

#include <lzf.h>

#include "antipode/core/error.hpp"
#include "pcd_ascii.hpp"
#include "pcd_header.hpp"
#include "raw_points.hpp"

namespace antipode::io {
namespace {

template <typename T>
float load_as_float(const char* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return static_cast<float>(value);
}

// The first value of `field` stored at `at`, as a float.
float value_at(const char* at, const PcdField& field) {
  switch (field.type) {
    case 'F':
      return field.size == 8 ? load_as_float<double>(at) : load_as_float<float>(at);
    case 'I':
      switch (field.size) {
        case 1:
          return load_as_float<std::int8_t>(at);
        case 2:
          return load_as_float<std::int16_t>(at);
        case 4:
          return load_as_float<std::int32_t>(at);
        default:
          return load_as_float<std::int64_t>(at);
      }
    default:
      switch (field.size) {
        case 1:
          return load_as_float<std::uint8_t>(at);
        case 2:
          return load_as_float<std::uint16_t>(at);
        case 4:
          return load_as_float<std::uint32_t>(at);
        default:
          return load_as_float<std::uint64_t>(at);
      }
  }
}

// Where point i's value of `f` starts in `data`: records of point_step bytes (binary), or
// one block per field holding that field for every point (binary_compressed, once unpacked).
std::size_t value_offset(const PcdHeader& header, const PcdField& f, std::size_t i, bool by_field) {
  return by_field ? f.offset * header.points + i * f.size * f.count
                  : i * header.point_step + f.offset;
}

// x, y, z of every point in `data`, and the `view` masks when the file has that field as
// save_cloud_pcd writes it (U, 4 bytes, one value).
RawPoints decode(const char* data, const PcdHeader& header, bool by_field) {
  const PcdField* axes[3] = {header.field("x"), header.field("y"), header.field("z")};
  RawPoints raw;
  raw.points_m.resize(header.points);
  for (int a = 0; a < 3; ++a)
    for (std::size_t i = 0; i < header.points; ++i)
      raw.points_m[i][a] = value_at(data + value_offset(header, *axes[a], i, by_field), *axes[a]);
  const PcdField* view = header.field("view");
  if (view != nullptr && view->type == 'U' && view->size == 4 && view->count == 1) {
    raw.view_masks.resize(header.points);
    for (std::size_t i = 0; i < header.points; ++i)
      std::memcpy(&raw.view_masks[i], data + value_offset(header, *view, i, by_field), 4);
  }
  return raw;
}

RawPoints read_compressed(const std::string& path, const std::string& bytes,
                          const PcdHeader& header) {
  // check_pcd_data_size() has checked both size fields against the header and the file.
  std::uint32_t compressed = 0;
  std::memcpy(&compressed, bytes.data() + header.data_offset, 4);
  std::vector<char> unpacked(header.points * header.point_step);
  const unsigned int size =
      lzf_decompress(bytes.data() + header.data_offset + 8, compressed, unpacked.data(),
                     static_cast<unsigned int>(unpacked.size()));
  if (size != unpacked.size()) {
    throw Error("corrupt PCD file: its compressed data cannot be decoded", {path});
  }
  return decode(unpacked.data(), header, true);
}

}  // namespace

RawPoints read_pcd(const std::string& path, const std::string& bytes) {
  const PcdHeader header = parse_pcd_header(path, bytes);
  check_pcd_data_size(path, bytes, header);
  RawPoints raw;
  if (header.points > 0) switch (header.data) {
      case PcdData::kAscii:
        raw.points_m = read_pcd_ascii_points(path, bytes, header);
        break;
      case PcdData::kBinary:
        raw = decode(bytes.data() + header.data_offset, header, false);
        break;
      case PcdData::kBinaryCompressed:
        raw = read_compressed(path, bytes, header);
        break;
    }
  raw.origin_m = header.viewpoint_m;
  raw.rotation = header.viewpoint_rotation;
  return raw;
}

}  // namespace antipode::io
