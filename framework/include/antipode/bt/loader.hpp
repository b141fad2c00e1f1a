#pragma once
/// @file
/// Loading and validating YAML tree files (the grammar is documented in docs/trees.md).
///
/// Both entry points validate the whole file before anything is created; the first problem
/// found is thrown as an antipode::Error whose what() reads `file:line:column: message`,
/// with a "did you mean" suggestion where a near name exists.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "antipode/bt/node_registry.hpp"
#include "antipode/bt/tree.hpp"
#include "antipode/plugin/component_source.hpp"

namespace antipode::bt {

struct LoadOptions {
  /// The node types the file may use; null means the built-in nodes only.
  const NodeRegistry* registry = nullptr;
  /// Creates the file's components; null is fine for files without `components`.
  const ComponentSource* components = nullptr;
  /// Seeds every node's random() stream.
  std::uint64_t seed = 0;
  /// `--set` entries as (key, value), applied in order before validation:
  /// "component.param" (or "component.a.b") sets a component parameter, with `value` read as
  /// YAML; a plain "key" sets the string entry {key} on the main tree's blackboard.
  std::vector<std::pair<std::string, std::string>> overrides;
  /// The tree to run instead of the file's `main` ("" = `main`); its blackboard is then the
  /// main blackboard (where `--set key=value` entries go). An unknown name is an error.
  std::string main_tree;
  /// validate_tree_*() only: whether to run the plugins' parameter checks (a caller that
  /// validates a file just before loading it, which makes the components, may skip them).
  bool check_component_parameters = true;
};

/// Reads, validates and builds the tree file at `path`: creates its components (through
/// `options.components`) and the nodes of its `main` tree.
Tree load_tree_file(const std::string& path, const LoadOptions& options);

/// Same for YAML text; `file_name` is used in messages.
Tree load_tree_string(const std::string& yaml, const std::string& file_name,
                      const LoadOptions& options);

/// Validates the file as load_tree_file() does but creates nothing: components are checked
/// for a known plugin type and their kind, and their parameters by their plugin's parameter
/// check (PluginParameterCheck, ComponentSource::check) where it has one; a plugin without
/// one has its parameters checked only at load.
void validate_tree_file(const std::string& path, const LoadOptions& options);

/// Same for YAML text.
void validate_tree_string(const std::string& yaml, const std::string& file_name,
                          const LoadOptions& options);

}  // namespace antipode::bt
