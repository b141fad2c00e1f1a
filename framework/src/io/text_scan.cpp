#include "text_scan.hpp"

#include <charconv>
#include <limits>

namespace antipode::io {

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::optional<std::uint64_t> parse_unsigned(std::string_view word) {
  std::uint64_t value = 0;
  const char* end = word.data() + word.size();
  const auto result = std::from_chars(word.data(), end, value);
  if (word.empty() || result.ec != std::errc() || result.ptr != end) return std::nullopt;
  return value;
}

std::optional<float> parse_float(std::string_view word) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  float value = 0.0f;
  const char* end = word.data() + word.size();
  const auto result = std::from_chars(word.data(), end, value);
  if (word.empty() || result.ptr != end) return std::nullopt;
  // A number beyond float's range is no usable coordinate: it is read as infinite, so the
  // point is dropped with the other non-finite ones.
  if (result.ec == std::errc::result_out_of_range) return std::numeric_limits<float>::infinity();
  if (result.ec != std::errc()) return std::nullopt;
  return value;
}

std::string quote_for_message(std::string_view text) {
  constexpr std::size_t kMaxLength = 24;
  std::string quoted;
  for (const char c : text.substr(0, kMaxLength)) {
    quoted += (c >= 32 && c < 127) ? c : '?';
  }
  if (text.size() > kMaxLength) quoted += "...";
  return "'" + quoted + "'";
}

std::string_view line_at(const std::string& bytes, std::size_t begin, std::size_t& next) {
  std::size_t end = bytes.find('\n', begin);
  next = end == std::string::npos ? bytes.size() : end + 1;
  if (end == std::string::npos) end = bytes.size();
  std::string_view line(bytes.data() + begin, end - begin);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

}  // namespace antipode::io
