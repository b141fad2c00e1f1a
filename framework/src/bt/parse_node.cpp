#include <cctype>

#include "parser.hpp"
#include "yaml_source.hpp"

namespace antipode::bt::detail {
namespace {

bool starts_upper(const std::string& text) {
  return !text.empty() && std::isupper(static_cast<unsigned char>(text[0]));
}

std::vector<std::string> known_keys(const NodeManifest& manifest) {
  std::vector<std::string> names = {"name"};
  for (const auto& port : manifest.ports) names.push_back(port.name);
  if (manifest.category == NodeCategory::kControl) names.push_back("children");
  if (manifest.category == NodeCategory::kDecorator) names.push_back("child");
  return names;
}

std::string plural(int count, const std::string& word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "ren");
}

std::string children_rule(const NodeManifest& manifest) {
  if (manifest.min_children == manifest.max_children) {
    return "exactly " + plural(manifest.min_children, "child");
  }
  if (manifest.max_children == -1) return "at least " + plural(manifest.min_children, "child");
  return "between " + std::to_string(manifest.min_children) + " and " +
         plural(manifest.max_children, "child");
}

void check_children(const NodeSpec& spec) {
  const NodeManifest& manifest = *spec.manifest;
  const int count = static_cast<int>(spec.children.size());
  if (count >= manifest.min_children &&
      (manifest.max_children == -1 || count <= manifest.max_children)) {
    return;
  }
  std::string hint;
  if (manifest.category == NodeCategory::kDecorator) hint = " (write it under 'child:')";
  throw Error(
      spec.type + " needs " + children_rule(manifest) + ", got " + std::to_string(count) + hint,
      spec.where);
}

void bind_missing_ports(NodeSpec& spec, const ParseContext& context) {
  for (const auto& info : spec.manifest->ports) {
    if (spec.ports.count(info.name) != 0) continue;
    if (info.required) {
      throw Error("missing required port '" + info.name + "' of " + spec.type, spec.where);
    }
    spec.ports.emplace(info.name,
                       default_binding(info, spec.where, context.registry->converters()));
  }
}

[[noreturn]] void unknown_port(const NodeSpec& spec, const YAML::Node& key,
                               const ParseContext& context) {
  const std::string& name = key.Scalar();
  std::string hint;
  if (context.registry->has(name)) {
    if (spec.manifest->category == NodeCategory::kControl) {
      hint = " (the children of " + spec.type + " go in a list: '" + spec.type +
             ": [...]' or 'children: [...]')";
    } else {
      hint = " (" + spec.type + " takes no children)";
    }
  }
  throw Error("unknown port '" + name + "' of " + spec.type +
                  did_you_mean(name, known_keys(*spec.manifest)) + hint,
              locate(key, context.file));
}

void parse_children(NodeSpec& spec, const YAML::Node& list, const ParseContext& context) {
  if (!list.IsSequence()) {
    throw Error("the children of " + spec.type + " must be a list of nodes",
                locate(list, context.file));
  }
  for (const auto& item : list) spec.children.push_back(parse_node(item, context));
}

void add_decorated_child(NodeSpec& spec, const YAML::Node& key, const YAML::Node& value,
                         const ParseContext& context) {
  if (!spec.children.empty()) {
    throw Error(spec.type + " needs exactly 1 child, found a second one",
                locate(key, context.file));
  }
  spec.children.push_back(key.Scalar() == "child" ? parse_node(value, context)
                                                  : parse_node_entry(key, value, context));
}

void parse_mapping(NodeSpec& spec, const YAML::Node& value, const ParseContext& context) {
  check_keys(value, context.file);
  const NodeCategory category = spec.manifest->category;
  for (const auto& entry : value) {
    const std::string key = entry.first.Scalar();
    if (key == "name") {
      if (!entry.second.IsScalar()) {
        throw Error("'name' of " + spec.type + " must be text",
                    locate_value(entry.first, entry.second, context.file));
      }
      spec.name = entry.second.Scalar();
    } else if (key == "children" && category == NodeCategory::kControl) {
      parse_children(spec, entry.second, context);
    } else if (category == NodeCategory::kDecorator &&
               (key == "child" || (starts_upper(key) && spec.manifest->port(key) == nullptr))) {
      add_decorated_child(spec, entry.first, entry.second, context);
    } else if (const PortInfo* info = spec.manifest->port(key)) {
      spec.ports[key] = bind_port(*info, spec.type, entry.first, entry.second, context);
    } else {
      unknown_port(spec, entry.first, context);
    }
  }
}

void parse_value(NodeSpec& spec, const YAML::Node& value, const ParseContext& context) {
  const NodeCategory category = spec.manifest->category;
  if (value.IsSequence()) {
    if (category != NodeCategory::kControl) {
      const std::string hint =
          category == NodeCategory::kDecorator ? " (write its child under 'child:')" : "";
      throw Error(spec.type + " takes a mapping of ports, not a list" + hint,
                  locate(value, context.file));
    }
    parse_children(spec, value, context);
  } else if (value.IsMap()) {
    parse_mapping(spec, value, context);
  } else if (value.IsDefined() && !value.IsNull()) {
    const std::string expected =
        category == NodeCategory::kControl ? " or a list of its children" : "";
    throw Error("the value of " + spec.type + " must be a mapping of its ports" + expected +
                    ", got '" + value.Scalar() + "'",
                locate(value, context.file));
  }
}

}  // namespace

NodeSpec parse_node(const YAML::Node& item, const ParseContext& context) {
  if (item.IsScalar()) return parse_node_entry(item, YAML::Node(), context);
  if (item.IsMap() && item.size() == 1) {
    const auto entry = item.begin();
    return parse_node_entry(entry->first, entry->second, context);
  }
  if (item.IsMap() && item.size() > 1) {
    check_keys(item, context.file);
    auto second = item.begin();
    const std::string first_key = second->first.Scalar();
    ++second;
    throw Error("a node is a one-key mapping {Type: ports}; this one has keys '" + first_key +
                    "' and '" + second->first.Scalar() + "'" +
                    indentation_hint(first_key, second->first.Scalar()),
                locate(second->first, context.file));
  }
  throw Error("expected a node such as 'AlwaysSuccess: {}', got " + describe_yaml(item),
              locate(item, context.file));
}

NodeSpec parse_node_entry(const YAML::Node& key, const YAML::Node& value,
                          const ParseContext& context) {
  const std::string& type = key.Scalar();
  if (!context.registry->has(type)) {
    throw UnknownTypeError(
        "unknown node '" + type + "'" + did_you_mean(type, context.registry->types()),
        locate(key, context.file));
  }
  NodeSpec spec;
  spec.manifest = &context.registry->get(type);
  spec.type = type;
  spec.where = locate(key, context.file);
  if (spec.manifest->category == NodeCategory::kSubTree) {
    parse_subtree_node(spec, value, context);
    return spec;
  }
  parse_value(spec, value, context);
  bind_missing_ports(spec, context);
  check_children(spec);
  return spec;
}

}  // namespace antipode::bt::detail
