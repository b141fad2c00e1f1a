#pragma once
// Whole-file checks that run after parsing: subtree cycles and blackboard entry types.

#include <string>
#include <utility>
#include <vector>

#include "antipode/bt/converters.hpp"
#include "tree_spec.hpp"

namespace antipode::bt::detail {

// Throws "subtree cycle: a -> b -> a" located at the SubTree node that closes a cycle.
void check_subtree_cycles(const FileSpec& spec);

// Every port that names an entry (across trees connected by SubTree remapping) must agree on
// its type. Converts SubTree literal inputs to the type their port is used as (stored in the
// RemapSpec) and checks that `--set` text entries of the main tree parse as their type.
void check_entry_types(FileSpec& spec, const LiteralConverters& converters,
                       const std::vector<std::pair<std::string, std::string>>& entry_overrides);

}  // namespace antipode::bt::detail
