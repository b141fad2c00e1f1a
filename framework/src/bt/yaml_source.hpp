#pragma once
// Reading YAML tree files and locating their nodes for messages.

#include <cstddef>
#include <string>

#include <yaml-cpp/yaml.h>

#include "antipode/core/error.hpp"

namespace antipode::bt::detail {

// The largest tree file read.
inline constexpr std::size_t kMaxTreeFileBytes = std::size_t(4) << 20;

// The contents of `path`; throws Error when it cannot be read or is over kMaxTreeFileBytes.
std::string read_text_file(const std::string& path);

// Parses `text`; a syntax error becomes Error "file:line:column: YAML syntax error: ...", and
// a document that expands to more than kMaxYamlNodes nodes an Error too.
YAML::Node parse_yaml(const std::string& text, const std::string& file);

// Where `node` starts in `file` (1-based), or just `file` when yaml-cpp has no mark.
SourceLocation locate(const YAML::Node& node, const std::string& file);

// The value's location, or the key's when the value is null (and so has no useful mark).
SourceLocation locate_value(const YAML::Node& key, const YAML::Node& value,
                            const std::string& file);

}  // namespace antipode::bt::detail
