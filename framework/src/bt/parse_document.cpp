#include <cctype>
#include <set>

#include "parser.hpp"
#include "yaml_source.hpp"

namespace antipode::bt::detail {
namespace {

const std::vector<std::string> kTopLevelKeys = {"settings", "components", "main", "trees"};
const std::vector<std::string> kDirections = {"input", "output", "inout"};

ComponentSpec parse_component(const YAML::Node& key, const YAML::Node& value,
                              const ParseContext& context) {
  ComponentSpec spec;
  spec.name = key.Scalar();
  spec.where = locate(key, context.file);
  spec.params.reset(value);
  const std::string owner = "component '" + spec.name + "'";
  if (!value.IsMap()) {
    throw Error(owner + " must be a mapping with a 'plugin' key and its parameters",
                locate_value(key, value, context.file));
  }
  check_keys(value, context.file);
  const YAML::Node plugin = value["plugin"];
  if (!plugin.IsDefined() || !plugin.IsScalar()) {
    throw Error(owner + " needs a 'plugin' key naming its type", spec.where);
  }
  spec.plugin = plugin.Scalar();
  const SourceLocation plugin_where = locate(plugin, context.file);
  if (context.components == nullptr) {
    throw Error(owner + " cannot be created: no plugin host is available", plugin_where);
  }
  const auto kind = context.components->kind_of(spec.plugin);
  if (!kind) {
    throw UnknownTypeError("unknown plugin type '" + spec.plugin + "' of " + owner +
                               did_you_mean(spec.plugin, context.components->component_types()),
                           plugin_where);
  }
  spec.kind = *kind;
  return spec;
}

std::vector<ComponentSpec> parse_components(const YAML::Node& node, const ParseContext& context) {
  std::vector<ComponentSpec> components;
  if (!node.IsDefined() || node.IsNull()) return components;
  if (!node.IsMap()) {
    throw Error("'components' must be a mapping of name: {plugin: type, ...}",
                locate(node, context.file));
  }
  check_keys(node, context.file);
  for (const auto& entry : node) {
    components.push_back(parse_component(entry.first, entry.second, context));
  }
  return components;
}

PortDirection parse_direction(const YAML::Node& key, const YAML::Node& value,
                              const std::string& tree, const std::string& file) {
  const std::string text = value.IsScalar() ? value.Scalar() : describe_yaml(value);
  if (text == "input") return PortDirection::kInput;
  if (text == "output") return PortDirection::kOutput;
  if (text == "inout") return PortDirection::kInOut;
  throw Error("port '" + key.Scalar() + "' of tree '" + tree +
                  "' must be input, output or inout, got '" + text + "'" +
                  did_you_mean(text, kDirections),
              locate_value(key, value, file));
}

std::vector<TreePortSpec> parse_tree_ports(const YAML::Node& node, const std::string& tree,
                                           const std::string& file) {
  if (!node.IsMap()) {
    throw Error("'ports' of tree '" + tree + "' must be a mapping of name: input|output|inout",
                locate(node, file));
  }
  check_keys(node, file);
  std::vector<TreePortSpec> ports;
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    if (!is_valid_key(name)) {
      throw Error("port '" + name + "' of tree '" + tree +
                      "' is not a valid entry name (a letter or '_', then letters, digits, '_')",
                  locate(entry.first, file));
    }
    ports.push_back(
        {name, parse_direction(entry.first, entry.second, tree, file), locate(entry.first, file)});
  }
  return ports;
}

// A tree's `ports` and the key/value of its one root node; the root is parsed later.
TreeSpec parse_tree_header(const YAML::Node& key, const YAML::Node& value,
                           const std::string& file) {
  TreeSpec spec;
  spec.name = key.Scalar();
  spec.where = locate(key, file);
  if (value.IsScalar()) {  // a bare node: `main: AlwaysSuccess`
    spec.root_key.reset(value);
    return spec;
  }
  if (!value.IsMap()) {
    throw Error("tree '" + spec.name + "' must be a mapping holding its root node",
                locate_value(key, value, file));
  }
  check_keys(value, file);
  std::vector<std::string> roots;
  for (const auto& entry : value) {
    if (entry.first.Scalar() == "ports") {
      spec.ports = parse_tree_ports(entry.second, spec.name, file);
      continue;
    }
    roots.push_back("'" + entry.first.Scalar() + "'");
    if (roots.size() == 1) {
      spec.root_key.reset(entry.first);
      spec.root_value.reset(entry.second);
    } else {
      throw Error("tree '" + spec.name + "' must have exactly one root node, found " + roots[0] +
                      " and " + roots[1] +
                      indentation_hint(spec.root_key.Scalar(), entry.first.Scalar()),
                  locate(entry.first, file));
    }
  }
  if (roots.empty()) throw Error("tree '" + spec.name + "' has no root node", spec.where);
  return spec;
}

std::vector<TreeSpec> parse_tree_headers(const YAML::Node& node, const std::string& file) {
  if (!node.IsMap() || node.size() == 0) {
    throw Error("'trees' must be a mapping of tree name: root node", locate(node, file));
  }
  check_keys(node, file);
  std::vector<TreeSpec> trees;
  for (const auto& entry : node)
    trees.push_back(parse_tree_header(entry.first, entry.second, file));
  return trees;
}

void check_top_level(const YAML::Node& document, const std::string& file) {
  if (!document.IsDefined() || document.IsNull()) {
    throw Error("the tree file is empty; it needs 'main' and 'trees'", {file});
  }
  if (!document.IsMap()) {
    throw Error("a tree file is a mapping with 'components', 'main' and 'trees'",
                locate(document, file));
  }
  check_keys(document, file);
  for (const auto& entry : document) {
    const std::string key = entry.first.Scalar();
    if (key != "settings" && key != "components" && key != "main" && key != "trees") {
      throw Error("unknown top-level key '" + key + "'" + did_you_mean(key, kTopLevelKeys),
                  locate(entry.first, file));
    }
  }
  if (!document["trees"].IsDefined()) {
    throw Error("the tree file has no 'trees'", {file, 1, 1});
  }
}

std::string parse_main(const YAML::Node& document, const FileSpec& spec) {
  const YAML::Node main = document["main"];
  std::vector<std::string> names;
  for (const auto& tree : spec.trees) names.push_back(tree.name);
  if (!main.IsDefined()) {
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
    throw Error("missing 'main': name the tree to run (one of: " + list + ")", {spec.file, 1, 1});
  }
  if (!main.IsScalar()) {
    throw Error("'main' must name a tree", locate(main, spec.file));
  }
  if (spec.tree(main.Scalar()) == nullptr) {
    throw Error(
        "unknown tree '" + main.Scalar() + "' in 'main'" + did_you_mean(main.Scalar(), names),
        locate(main, spec.file));
  }
  return main.Scalar();
}

}  // namespace

FileSpec parse_document(const YAML::Node& document, const ParseContext& context) {
  check_top_level(document, context.file);
  FileSpec spec;
  spec.file = context.file;
  ParseContext inner = context;
  inner.spec = &spec;
  spec.components = parse_components(document["components"], inner);
  spec.trees = parse_tree_headers(document["trees"], context.file);
  spec.main = parse_main(document, spec);
  for (auto& tree : spec.trees) {
    tree.root = parse_node_entry(tree.root_key, tree.root_value, inner);
  }
  return spec;
}

void check_keys(const YAML::Node& map, const std::string& file) {
  std::set<std::string> seen;
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) {
      throw Error("keys must be plain names", locate(entry.first, file));
    }
    if (!seen.insert(entry.first.Scalar()).second) {
      throw Error("duplicate key '" + entry.first.Scalar() + "'", locate(entry.first, file));
    }
  }
}

// " (are the ports of X indented under it?)" when `second` looks like a port of `first`.
std::string indentation_hint(const std::string& first, const std::string& second) {
  if (second.empty() || !std::islower(static_cast<unsigned char>(second[0]))) return {};
  return " (are the ports of " + first + " indented under it?)";
}

std::vector<std::string> key_names(const YAML::Node& map) {
  std::vector<std::string> names;
  for (const auto& entry : map) names.push_back(entry.first.Scalar());
  return names;
}

}  // namespace antipode::bt::detail
