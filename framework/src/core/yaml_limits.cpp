#include "antipode/core/yaml_limits.hpp"

#include <vector>

#include <filesystem>

#include "antipode/core/error.hpp"
#include "antipode/core/input_file.hpp"

namespace antipode {

void check_yaml_size(const YAML::Node& node, const std::string& what, std::size_t limit) {
  // Depth first with an explicit stack: a deeply nested document cannot overflow the C stack.
  std::vector<YAML::Node> pending{node};
  std::size_t count = 0;
  while (!pending.empty()) {
    const YAML::Node next = pending.back();
    pending.pop_back();
    if (++count > limit) {
      throw Error(what + ": more than " + std::to_string(limit) +
                  " YAML nodes once its aliases are expanded");
    }
    if (next.IsSequence()) {
      for (const auto& item : next) pending.push_back(item);
    } else if (next.IsMap()) {
      for (const auto& entry : next) {
        pending.push_back(entry.first);
        pending.push_back(entry.second);
      }
    }
  }
}

YAML::Node load_yaml_map(const std::string& path, const std::string& what, const std::string& kind,
                         const std::string& examples) {
  const std::string see = " (see " + examples + ")";
  require_regular_file(path, "a YAML map of " + kind + see);
  if (!std::filesystem::exists(path)) throw Error(what + ": no such file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw Error(what + ": " + e.what());
  }
  check_yaml_size(root, what);
  if (!root.IsMap()) {
    throw Error(what + ": " +
                (root.IsNull() ? std::string("the file is empty") : "not a map of " + kind) + see);
  }
  return root;
}

}  // namespace antipode
