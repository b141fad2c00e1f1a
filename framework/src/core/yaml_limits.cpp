#include "antipode/core/yaml_limits.hpp"

#include <vector>

#include "antipode/core/error.hpp"

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

}  // namespace antipode
