#include "antipode/bt/loader.hpp"

#include "antipode/core/error.hpp"

#include "build_tree.hpp"
#include "checks.hpp"
#include "overrides.hpp"
#include "parser.hpp"
#include "settings.hpp"
#include "yaml_source.hpp"

namespace antipode::bt {
namespace {

const NodeRegistry& registry_of(const LoadOptions& options) {
  if (options.registry != nullptr) return *options.registry;
  static const NodeRegistry builtin = builtin_node_registry();
  return builtin;
}

struct CheckedFile {
  detail::FileSpec spec;
  detail::Overrides entries;  // `--set key=value` entries of the main blackboard
};

CheckedFile check_file(const std::string& yaml, const std::string& file_name,
                       const LoadOptions& options) {
  YAML::Node document = detail::parse_yaml(yaml, file_name);
  CheckedFile checked;
  checked.entries = detail::apply_settings(
      document, detail::apply_overrides(document, options.overrides), file_name);
  detail::ParseContext context;
  context.file = file_name;
  context.registry = &registry_of(options);
  context.components = options.components;
  checked.spec = detail::parse_document(document, context);
  if (checked.spec.trees.size() > detail::kMaxTrees) {
    throw Error(file_name + ": " + std::to_string(checked.spec.trees.size()) +
                " trees, more than the " + std::to_string(detail::kMaxTrees) + " a file may hold");
  }
  if (!options.main_tree.empty()) {
    if (checked.spec.tree(options.main_tree) == nullptr) {
      std::vector<std::string> names;
      for (const auto& tree : checked.spec.trees) names.push_back(tree.name);
      throw Error(file_name + ": no tree '" + options.main_tree + "' to run" +
                  did_you_mean(options.main_tree, names));
    }
    checked.spec.main = options.main_tree;
  }
  detail::check_subtree_cycles(checked.spec);
  detail::check_entry_types(checked.spec, context.registry->converters(), checked.entries);
  return checked;
}

// Each declared component's parameters, as its plugin checks them without making it.
void check_component_parameters(const detail::FileSpec& spec, const ComponentSource* source) {
  if (source == nullptr) return;
  for (const auto& declared : spec.components) {
    const std::string owner = "component '" + declared.name + "'";
    Parameters params(declared.params, owner, spec.file);
    params.require<std::string>("plugin");  // known to the loader, not to the plugin
    try {
      source->check(declared.plugin, params);
    } catch (...) {
      rethrow_with_context(owner, declared.where);
    }
  }
}

}  // namespace

Tree load_tree_string(const std::string& yaml, const std::string& file_name,
                      const LoadOptions& options) {
  const CheckedFile checked = check_file(yaml, file_name, options);
  detail::TreeBuilder builder{
      checked.spec, options.components,
      std::make_shared<const LiteralConverters>(registry_of(options).converters()), options.seed,
      nullptr};
  return builder.build(checked.entries);
}

Tree load_tree_file(const std::string& path, const LoadOptions& options) {
  return load_tree_string(detail::read_text_file(path), path, options);
}

void validate_tree_string(const std::string& yaml, const std::string& file_name,
                          const LoadOptions& options) {
  const CheckedFile checked = check_file(yaml, file_name, options);
  if (options.check_component_parameters)
    check_component_parameters(checked.spec, options.components);
}

void validate_tree_file(const std::string& path, const LoadOptions& options) {
  validate_tree_string(detail::read_text_file(path), path, options);
}

}  // namespace antipode::bt
