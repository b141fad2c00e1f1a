#include "antipode/core/parameters.hpp"

#include <cmath>
#include <filesystem>
#include <string>

namespace antipode {

Parameters::Parameters(const YAML::Node& node, std::string owner, std::string file)
    : node_(node), owner_(std::move(owner)), file_(std::move(file)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw Error("parameters of " + owner_ + " must be a mapping of key: value", location(""));
  }
}

bool Parameters::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

double Parameters::number_in(const std::string& key, double fallback, double lo, double hi) const {
  const double value = get<double>(key, fallback);
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    const auto text = [](double v) {
      std::string s = std::to_string(v);
      s.erase(s.find_last_not_of('0') + 1);
      if (!s.empty() && s.back() == '.') s.pop_back();
      return s;
    };
    fail(key, "parameter '" + key + "' must be in [" + text(lo) + ", " + text(hi) + "], got " +
                  text(value));
  }
  return value;
}

Parameters Parameters::child(const std::string& key) const {
  asked_.insert(key);
  if (!has(key)) return Parameters(YAML::Node(YAML::NodeType::Map), owner_ + "." + key, file_);
  return Parameters(node_[key], owner_ + "." + key, file_);
}

void Parameters::reject_unknown() const {
  if (!node_.IsMap()) return;
  const std::vector<std::string> known(asked_.begin(), asked_.end());
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) {
      const YAML::Mark mark = entry.first.Mark();
      throw Error("a parameter of " + owner_ + " is named by a list or a mapping, not a name",
                  file_.empty() || mark.is_null()
                      ? SourceLocation{}
                      : SourceLocation{file_, mark.line + 1, mark.column + 1});
    }
    const auto key = entry.first.Scalar();
    if (asked_.count(key) == 0) {
      fail(key, "unknown parameter '" + key + "' of " + owner_ + did_you_mean(key, known));
    }
  }
}

SourceLocation Parameters::location(const std::string& key) const {
  YAML::Mark mark = node_.Mark();
  if (!key.empty() && node_.IsMap()) {
    for (const auto& entry : node_) {
      if (entry.first.Scalar() != key) continue;
      // A value without a position was not read from the file: `--set` put it there.
      if (!file_.empty() && entry.second.Mark().is_null()) return {"--set", 0, 0};
      mark = entry.first.Mark();
    }
  }
  if (file_.empty()) return {};
  if (mark.is_null()) return {file_, 0, 0};
  return {file_, mark.line + 1, mark.column + 1};
}

void Parameters::fail(const std::string& key, const std::string& message) const {
  throw Error(message, location(key));
}

std::string Parameters::scalar_text(const std::string& key) const {
  const YAML::Node value = node_[key];
  if (value.IsScalar()) return value.Scalar();
  if (value.IsSequence()) return "a list";
  if (value.IsMap()) return "a mapping";
  return "nothing";
}

std::string resolve_path(const std::string& path, const std::string& yaml_file) {
  namespace fs = std::filesystem;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path) || yaml_file.empty())
    return path;
  const fs::path dir = fs::path(yaml_file).parent_path();
  for (const fs::path& base : {dir, dir.parent_path()})
    if (fs::exists(base / path)) return (base / path).string();
  return path;
}

}  // namespace antipode
