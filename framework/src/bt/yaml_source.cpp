#include "yaml_source.hpp"

#include <fstream>
#include <sstream>

#include "antipode/core/input_file.hpp"
#include "antipode/core/yaml_limits.hpp"

namespace antipode::bt::detail {

std::string read_text_file(const std::string& path) {
  require_regular_file(path, "a tree file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read tree file '" + path + "'", {path});
  in.seekg(0, std::ios::end);
  if (in.tellg() > std::streamoff(kMaxTreeFileBytes)) {
    throw Error(
        "the tree file is larger than " + std::to_string(kMaxTreeFileBytes >> 20) + " MB; split it",
        {path});
  }
  in.seekg(0, std::ios::beg);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error("cannot read tree file '" + path + "'", {path});
  return text.str();
}

YAML::Node parse_yaml(const std::string& text, const std::string& file) {
  try {
    YAML::Node document = YAML::Load(text);
    check_yaml_size(document, file);
    return document;
  } catch (const YAML::ParserException& error) {
    const SourceLocation where{file, error.mark.line + 1, error.mark.column + 1};
    throw Error("YAML syntax error: " + error.msg,
                error.mark.is_null() ? SourceLocation{file} : where);
  }
}

SourceLocation locate(const YAML::Node& node, const std::string& file) {
  if (!node.IsDefined()) return {file};
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {file};
  return {file, mark.line + 1, mark.column + 1};
}

SourceLocation locate_value(const YAML::Node& key, const YAML::Node& value,
                            const std::string& file) {
  if (!value.IsDefined() || value.IsNull()) return locate(key, file);
  return locate(value, file);
}

}  // namespace antipode::bt::detail
