#include "pcd_ascii.hpp"

#include <array>

#include "antipode/core/error.hpp"
#include "text_scan.hpp"

namespace antipode::io {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Splits one data line into at most `limit` words; returns how many it found (a value
// above `limit` only means "more").
std::size_t split_line(std::string_view line, std::size_t limit, std::string_view* words) {
  std::size_t found = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i == start) break;
    if (found < limit) words[found] = line.substr(start, i - start);
    ++found;
  }
  return found;
}

class AsciiReader {
 public:
  AsciiReader(const std::string& path, const std::string& bytes, const PcdHeader& header)
      : path_(path), bytes_(bytes), header_(header) {
    columns_ = {header.field("x")->column, header.field("y")->column, header.field("z")->column};
    words_.resize(header.values_per_point);
  }

  std::vector<Eigen::Vector3f> read() {
    std::vector<Eigen::Vector3f> points;
    points.reserve(header_.points);
    std::size_t offset = header_.data_offset;
    int line_number = header_.data_line - 1;
    while (points.size() < header_.points && offset < bytes_.size()) {
      std::size_t next = 0;
      const std::string_view line = line_at(bytes_, offset, next);
      offset = next;
      ++line_number;
      const std::size_t found = split_line(line, words_.size(), words_.data());
      if (found == 0) continue;
      if (found < words_.size()) {
        fail(line_number, "data line has " + std::to_string(found) + " values, the header " +
                              "declares " + std::to_string(words_.size()));
      }
      points.push_back(point(line_number));
    }
    if (points.size() < header_.points) {
      throw Error("truncated PCD file: the header declares " + std::to_string(header_.points) +
                      " points but the data holds " + std::to_string(points.size()),
                  {path_});
    }
    return points;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw Error(message, {path_, line, 0});
  }

  Eigen::Vector3f point(int line_number) const {
    Eigen::Vector3f p;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string_view word = words_[columns_[static_cast<std::size_t>(axis)]];
      const auto value = parse_float(word);
      if (!value) fail(line_number, "coordinate " + quote_for_message(word) + " is not a number");
      p[axis] = *value;
    }
    return p;
  }

  const std::string& path_;
  const std::string& bytes_;
  const PcdHeader& header_;
  std::array<std::size_t, 3> columns_{};
  std::vector<std::string_view> words_;
};

}  // namespace

std::vector<Eigen::Vector3f> read_pcd_ascii_points(const std::string& path,
                                                   const std::string& bytes,
                                                   const PcdHeader& header) {
  return AsciiReader(path, bytes, header).read();
}

}  // namespace antipode::io
