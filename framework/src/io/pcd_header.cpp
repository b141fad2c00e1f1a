#include "pcd_header.hpp"

#include <limits>

#include "antipode/core/error.hpp"
#include "text_scan.hpp"

namespace antipode::io {
namespace {

// Indices are 32-bit signed integers throughout antipode.
constexpr std::uint64_t kMaxPoints = std::numeric_limits<std::int32_t>::max();
// A real header is a few hundred bytes; anything longer without DATA is not a PCD file.
constexpr std::size_t kMaxHeaderBytes = std::size_t{64} * 1024;

using Words = std::vector<std::string_view>;

class HeaderParser {
 public:
  HeaderParser(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  PcdHeader parse() {
    std::size_t offset = 0;
    while (offset < bytes_.size() && offset < kMaxHeaderBytes) {
      std::size_t next = 0;
      const std::string_view line = line_at(bytes_, offset, next);
      ++line_;
      offset = next;
      const Words words = split_words(line);
      if (words.empty() || words.front().front() == '#') continue;
      if (handle(words)) {
        header_.data_offset = offset;
        header_.data_line = line_ + 1;
        finish();
        return header_;
      }
    }
    throw Error("not a PCD file: no DATA line in its header", {path_});
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(message, {path_, line_, 0});
  }

  // Returns true for the DATA line, which ends the header.
  bool handle(const Words& words) {
    const std::string_view key = words.front();
    if (key == "VERSION") return false;
    if (key == "FIELDS" || key == "COLUMNS") return set_fields(words), false;
    if (key == "SIZE") return set_sizes(words), false;
    if (key == "TYPE") return set_types(words), false;
    if (key == "COUNT") return set_counts(words), false;
    if (key == "WIDTH") return header_.width = number(words), false;
    if (key == "HEIGHT") return header_.height = number(words), false;
    if (key == "POINTS") return points_line_ = line_, points_ = number(words), false;
    if (key == "VIEWPOINT") return set_viewpoint(words), false;
    if (key == "DATA") return set_data(words), true;
    fail("not a PCD header line: " + quote_for_message(key));
  }

  void expect_per_field(const Words& words) const {
    if (header_.fields.empty()) fail(std::string(words.front()) + " before FIELDS");
    if (words.size() != header_.fields.size() + 1) {
      fail(std::string(words.front()) + " has " + std::to_string(words.size() - 1) +
           " entries for " + std::to_string(header_.fields.size()) + " fields");
    }
  }

  std::uint64_t number(const Words& words) const {
    const auto value = words.size() == 2 ? parse_unsigned(words[1]) : std::nullopt;
    if (!value) fail(std::string(words.front()) + " must be one non-negative integer");
    if (*value > kMaxPoints) {
      fail(std::string(words.front()) + " " + std::to_string(*value) + " is too large");
    }
    return *value;
  }

  void set_fields(const Words& words) {
    if (words.size() < 2) fail("FIELDS names no field");
    header_.fields.clear();
    for (std::size_t i = 1; i < words.size(); ++i) {
      header_.fields.push_back(PcdField{std::string(words[i])});
    }
  }

  void set_sizes(const Words& words) {
    expect_per_field(words);
    for (std::size_t i = 1; i < words.size(); ++i) {
      const auto size = parse_unsigned(words[i]);
      if (!size || (*size != 1 && *size != 2 && *size != 4 && *size != 8)) {
        fail("SIZE " + quote_for_message(words[i]) + " is not 1, 2, 4 or 8");
      }
      header_.fields[i - 1].size = *size;
    }
  }

  void set_types(const Words& words) {
    expect_per_field(words);
    for (std::size_t i = 1; i < words.size(); ++i) {
      if (words[i] != "F" && words[i] != "I" && words[i] != "U") {
        fail("TYPE " + quote_for_message(words[i]) + " is not F, I or U");
      }
      header_.fields[i - 1].type = words[i].front();
    }
  }

  void set_counts(const Words& words) {
    expect_per_field(words);
    for (std::size_t i = 1; i < words.size(); ++i) {
      const auto count = parse_unsigned(words[i]);
      if (!count || *count == 0 || *count > std::uint64_t{1024} * 1024) {
        fail("COUNT " + quote_for_message(words[i]) + " is not a positive integer");
      }
      header_.fields[i - 1].count = *count;
    }
  }

  void set_viewpoint(const Words& words) {
    if (words.size() != 8) fail("VIEWPOINT must have 7 numbers (tx ty tz qw qx qy qz)");
    float v[7];
    for (int i = 0; i < 7; ++i) {
      const auto value = parse_float(words[i + 1]);
      if (!value) fail("VIEWPOINT " + quote_for_message(words[i + 1]) + " is not a number");
      v[i] = *value;
    }
    const Eigen::Vector3f origin(v[0], v[1], v[2]);
    if (!origin.allFinite()) fail("VIEWPOINT origin is not finite");
    Eigen::Quaternionf rotation(v[3], v[4], v[5], v[6]);
    if (!rotation.coeffs().allFinite() || rotation.norm() < 1e-6f)
      fail("VIEWPOINT rotation (qw qx qy qz) is not a rotation: zero or not finite");
    header_.viewpoint_m = origin;
    header_.viewpoint_rotation = rotation.normalized();
  }

  void set_data(const Words& words) {
    if (words.size() != 2) fail("DATA must be ascii, binary or binary_compressed");
    if (words[1] == "ascii")
      header_.data = PcdData::kAscii;
    else if (words[1] == "binary")
      header_.data = PcdData::kBinary;
    else if (words[1] == "binary_compressed")
      header_.data = PcdData::kBinaryCompressed;
    else
      fail("DATA " + quote_for_message(words[1]) + " is not ascii, binary or binary_compressed");
  }

  void finish() {
    if (header_.fields.empty()) fail("the header has no FIELDS line");
    std::size_t offset = 0;
    std::size_t column = 0;
    for (auto& field : header_.fields) {
      if (field.type == 'F' && field.size != 4 && field.size != 8) {
        fail("field '" + field.name + "' is a float of size " + std::to_string(field.size));
      }
      field.offset = offset;
      field.column = column;
      offset += field.size * field.count;
      column += field.count;
    }
    header_.point_step = offset;
    header_.values_per_point = column;
    check_coordinates();
    check_point_count();
  }

  void check_coordinates() const {
    for (const char* name : {"x", "y", "z"}) {
      const PcdField* field = header_.field(name);
      if (field == nullptr) fail(std::string("the cloud has no '") + name + "' field");
      if (field->type != 'F') fail(std::string("field '") + name + "' is not of type F");
    }
  }

  void check_point_count() {
    if (header_.height == 0 && header_.width != 0) fail("HEIGHT is 0");
    const std::uint64_t grid = header_.width * header_.height;
    if (grid > kMaxPoints) fail("WIDTH * HEIGHT is too large");
    if (points_ && *points_ != grid) {
      line_ = points_line_;
      fail("POINTS " + std::to_string(*points_) +
           " differs from WIDTH * HEIGHT = " + std::to_string(grid));
    }
    header_.points = grid;
  }

  const std::string& path_;
  const std::string& bytes_;
  int line_ = 0;
  PcdHeader header_;
  std::optional<std::uint64_t> points_;
  int points_line_ = 0;
};

std::uint32_t read_u32_le(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
  }
  return value;
}

}  // namespace

const PcdField* PcdHeader::field(const std::string& name) const {
  for (const auto& f : fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

PcdHeader parse_pcd_header(const std::string& path, const std::string& bytes) {
  return HeaderParser(path, bytes).parse();
}

void check_pcd_data_size(const std::string& path, const std::string& bytes,
                         const PcdHeader& header) {
  const std::uint64_t available = bytes.size() - header.data_offset;
  const std::uint64_t needed = header.points * header.point_step;
  const std::string declared = "the header declares " + std::to_string(header.points) + " points";
  if (header.data == PcdData::kAscii) {
    // Each value takes at least one character and one separator.
    if (header.points > 0 && available < header.points * header.values_per_point) {
      throw Error("truncated PCD file: " + declared + " but the data holds only " +
                      std::to_string(available) + " bytes",
                  {path});
    }
    return;
  }
  if (header.data == PcdData::kBinary) {
    if (available < needed) {
      throw Error("truncated PCD file: " + declared + " (" + std::to_string(needed) +
                      " bytes) but the data holds " + std::to_string(available) + " bytes",
                  {path});
    }
    return;
  }
  if (header.points == 0) return;
  if (available < 8) throw Error("truncated PCD file: the compressed data is missing", {path});
  const std::uint64_t compressed = read_u32_le(bytes, header.data_offset);
  const std::uint64_t uncompressed = read_u32_le(bytes, header.data_offset + 4);
  if (uncompressed != needed) {
    throw Error("corrupt PCD file: " + declared + " (" + std::to_string(needed) +
                    " bytes) but the compressed data unpacks to " + std::to_string(uncompressed),
                {path});
  }
  if (available - 8 < compressed) {
    throw Error("truncated PCD file: the compressed data should hold " +
                    std::to_string(compressed) + " bytes but the file has " +
                    std::to_string(available - 8),
                {path});
  }
}

}  // namespace antipode::io
