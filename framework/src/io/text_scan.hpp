#pragma once
// Internal to the io area: small helpers for scanning header and ascii-data text.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace antipode::io {

/// Splits `line` at spaces and tabs (runs count as one separator).
std::vector<std::string_view> split_words(std::string_view line);

/// The whole of `word` as a non-negative integer, or nothing.
std::optional<std::uint64_t> parse_unsigned(std::string_view word);

/// The whole of `word` as a float ("nan", "inf" and a leading '+' accepted), or nothing.
std::optional<float> parse_float(std::string_view word);

/// `text` made printable and short enough to quote in a one-line message.
std::string quote_for_message(std::string_view text);

/// The line starting at `begin` (without its "\n" or "\r\n"); `next` receives the offset
/// just past the line break (or bytes.size()).
std::string_view line_at(const std::string& bytes, std::size_t begin, std::size_t& next);

}  // namespace antipode::io
