#include "parser.hpp"
#include "yaml_source.hpp"

namespace antipode::bt::detail {
namespace {

const std::vector<std::string> kSubTreeKeys = {"tree", "ports", "name"};

std::string tree_port(const std::string& port, const TreeSpec& tree) {
  return "port '" + port + "' of tree '" + tree.name + "'";
}

RemapSpec parse_remap(const YAML::Node& key, const YAML::Node& value, const TreeSpec& target,
                      const ParseContext& context) {
  const std::string port = key.Scalar();
  const TreePortSpec* declared = target.port(port);
  if (declared == nullptr) {
    std::vector<std::string> names;
    for (const auto& candidate : target.ports) names.push_back(candidate.name);
    const std::string hint = names.empty() ? " (tree '" + target.name +
                                                 "' declares no ports; list them under its "
                                                 "'ports:')"
                                           : did_you_mean(port, names);
    throw Error("unknown port '" + port + "' of tree '" + target.name + "'" + hint,
                locate(key, context.file));
  }
  RemapSpec remap;
  remap.port = port;
  remap.direction = declared->direction;
  remap.key_where = locate(key, context.file);
  remap.where = locate_value(key, value, context.file);
  // Bind it like a node port of type `any` to share the reference rules and messages.
  PortInfo info = remap.direction == PortDirection::kInput ? input_port<std::any>(port, "")
                                                           : output_port<std::any>(port, "");
  info.direction = remap.direction;
  if (remap.direction == PortDirection::kInput && value.IsSequence()) {
    remap.literal.reset(value);  // a list literal, converted by the type check
    return remap;
  }
  const PortBinding bound = bind_port(info, "tree '" + target.name + "'", key, value, context);
  if (bound.source == PortBinding::Source::kEntry) {
    remap.parent_key = bound.key;
  } else {
    remap.literal.reset(value);
  }
  return remap;
}

void parse_remaps(NodeSpec& spec, const TreeSpec& target, const YAML::Node& node,
                  const ParseContext& context) {
  if (!node.IsMap()) {
    throw Error("'ports' of SubTree must be a mapping of subtree port: \"{entry}\" or literal",
                locate(node, context.file));
  }
  check_keys(node, context.file);
  for (const auto& entry : node) {
    spec.remaps.push_back(parse_remap(entry.first, entry.second, target, context));
  }
  for (const auto& declared : target.ports) {
    if (declared.direction == PortDirection::kOutput) continue;
    bool given = false;
    for (const auto& remap : spec.remaps) given = given || remap.port == declared.name;
    if (!given) {
      throw Error("missing required " + tree_port(declared.name, target), spec.where);
    }
  }
}

}  // namespace

void parse_subtree_node(NodeSpec& spec, const YAML::Node& value, const ParseContext& context) {
  // YAML::Node::operator= writes through to the referenced node; reset() rebinds.
  YAML::Node tree_key;
  YAML::Node tree_value;
  YAML::Node remaps;
  if (value.IsMap()) {
    check_keys(value, context.file);
    for (const auto& entry : value) {
      const std::string key = entry.first.Scalar();
      if (key == "tree") {
        tree_key.reset(entry.first);
        tree_value.reset(entry.second);
      } else if (key == "ports") {
        remaps.reset(entry.second);
      } else if (key == "name") {
        if (!entry.second.IsScalar()) {
          throw Error("'name' of SubTree must be text",
                      locate_value(entry.first, entry.second, context.file));
        }
        spec.name = entry.second.Scalar();
      } else {
        throw Error("unknown port '" + key + "' of SubTree" + did_you_mean(key, kSubTreeKeys),
                    locate(entry.first, context.file));
      }
    }
  } else {
    tree_key.reset(value);
    tree_value.reset(value);
  }
  if (!tree_value.IsDefined() || tree_value.IsNull()) {
    throw Error("missing required port 'tree' of SubTree", spec.where);
  }
  spec.subtree_where = locate(tree_value, context.file);
  if (!tree_value.IsScalar())
    throw Error("port 'tree' of SubTree must name a tree", spec.subtree_where);
  const std::string name = tree_value.Scalar();
  const TreeSpec* target = context.spec->tree(name);
  if (target == nullptr) {
    std::vector<std::string> names;
    for (const auto& tree : context.spec->trees) names.push_back(tree.name);
    throw Error("unknown tree '" + name + "' in SubTree" + did_you_mean(name, names),
                spec.subtree_where);
  }
  spec.subtree = name;
  PortBinding tree_binding =
      bind_port(*spec.manifest->port("tree"), "SubTree", tree_key, tree_value, context);
  spec.ports.emplace("tree", std::move(tree_binding));
  if (remaps.IsDefined() && !remaps.IsNull()) {
    parse_remaps(spec, *target, remaps, context);
  } else if (!target->ports.empty()) {
    parse_remaps(spec, *target, YAML::Node(YAML::NodeType::Map), context);
  }
}

}  // namespace antipode::bt::detail
