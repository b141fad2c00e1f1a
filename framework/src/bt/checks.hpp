#pragma once
// Whole-file checks that run after parsing (subtree cycles and blackboard entry types) and one
// that runs once the components exist (classifiers against samplers' hands).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "antipode/bt/converters.hpp"
#include "tree_context.hpp"
#include "tree_spec.hpp"

namespace antipode::bt::detail {

// How deep SubTree nodes may nest, and how many trees a file may hold.
inline constexpr std::size_t kMaxSubtreeDepth = 64;
inline constexpr std::size_t kMaxTrees = 1000;

// Throws "subtree cycle: a -> b -> a" located at the SubTree node that closes a cycle, and an
// Error when subtrees nest deeper than kMaxSubtreeDepth.
void check_subtree_cycles(const FileSpec& spec);

// Every port that names an entry (across trees connected by SubTree remapping) must agree on
// its type. Converts SubTree literal inputs to the type their port is used as (stored in the
// RemapSpec) and checks that `--set` text entries of the main tree parse as their type.
void check_entry_types(FileSpec& spec, const LiteralConverters& converters,
                       const std::vector<std::pair<std::string, std::string>>& entry_overrides);

// Throws, located at the classifier's declaration, when a classifier of the tree refuses the
// hand of one of its samplers (Classifier::hand_problem of Sampler::hand).
void check_classifiers_fit_samplers(const FileSpec& spec, const TreeContext& context);

}  // namespace antipode::bt::detail
