#include "parser.hpp"
#include "yaml_source.hpp"

namespace antipode::bt::detail {
namespace {

// A YAML value as shown in messages: 'text' for scalars, "a list", "a mapping", "nothing".
std::string shown(const YAML::Node& value) {
  return value.IsScalar() ? "'" + value.Scalar() + "'" : describe_yaml(value);
}

// `{cloud}` written without quotes: YAML reads it as the mapping {cloud: null}.
void reject_unquoted_reference(const std::string& port, const YAML::Node& value,
                               const SourceLocation& where) {
  if (!value.IsMap() || value.size() != 1) return;
  const auto entry = value.begin();
  if (!entry->first.IsScalar() || !entry->second.IsNull()) return;
  const std::string key = entry->first.Scalar();
  throw Error(
      port + ": write \"{" + key + "}\" in quotes; unquoted, YAML reads {" + key + "} as a mapping",
      where);
}

bool looks_like_reference(const std::string& text) {
  return text.size() >= 2 && text.front() == '{' && text.back() == '}';
}

[[noreturn]] void bad_reference(const std::string& port, const std::string& text,
                                const SourceLocation& where) {
  throw Error(port + " has a bad blackboard reference '" + text +
                  "': an entry name is a letter or '_' followed by letters, digits or '_'",
              where);
}

PortBinding bind_entry_port(PortBinding binding, const std::string& port, const YAML::Node& value) {
  const std::string text = value.IsScalar() ? value.Scalar() : std::string();
  if (auto key = parse_reference(text)) {
    binding.key = *key;
  } else if (is_valid_key(text)) {
    binding.key = text;
  } else {
    if (looks_like_reference(text)) bad_reference(port, text, binding.where);
    throw Error(port + " is an " + to_string(binding.info.direction) +
                    " and must name a blackboard entry such as \"{" + binding.info.name +
                    "}\", got " + shown(value),
                binding.where);
  }
  binding.source = PortBinding::Source::kEntry;
  return binding;
}

PortBinding bind_component_port(PortBinding binding, const std::string& port,
                                const YAML::Node& value, const ParseContext& context) {
  if (!value.IsScalar()) throw Error(port + " must name a component", binding.where);
  const std::string name = value.Scalar();
  if (parse_reference(name)) {
    throw Error(port + " names a component; write its name, not a blackboard entry", binding.where);
  }
  const ComponentSpec* component = context.spec->component(name);
  if (component == nullptr) {
    std::vector<std::string> names;
    for (const auto& declared : context.spec->components) names.push_back(declared.name);
    const std::string hint = names.empty() ? " (declare it under 'components:')" : "";
    throw Error("unknown component '" + name + "' in " + port + did_you_mean(name, names) + hint,
                binding.where);
  }
  const ComponentKind wanted = *binding.info.component_kind;
  if (component->kind != wanted) {
    throw Error("component '" + name + "' is a " + to_string(component->kind) + ", but " + port +
                    " needs a " + to_string(wanted),
                binding.where);
  }
  binding.source = PortBinding::Source::kLiteral;
  binding.value = name;
  binding.literal.reset(value);
  return binding;
}

PortBinding bind_literal_port(PortBinding binding, const std::string& port, const YAML::Node& value,
                              const ParseContext& context) {
  const LiteralConverters& converters = context.registry->converters();
  if (!converters.can_parse(binding.info.type)) {
    throw Error(port + " takes " + binding.info.type_name +
                    " from a blackboard entry; write \"{name}\", not " + shown(value),
                binding.where);
  }
  auto converted = converters.parse(binding.info.type, value);
  if (!converted) {
    throw Error(port + " expects " + binding.info.type_name + ", got " + shown(value),
                binding.where);
  }
  binding.source = PortBinding::Source::kLiteral;
  binding.value = std::move(*converted);
  binding.literal.reset(value);
  return binding;
}

}  // namespace

PortBinding bind_port(const PortInfo& info, const std::string& node, const YAML::Node& key,
                      const YAML::Node& value, const ParseContext& context) {
  PortBinding binding;
  binding.info = info;
  binding.where = locate_value(key, value, context.file);
  const std::string port = "port '" + info.name + "' of " + node;
  reject_unquoted_reference(port, value, binding.where);
  if (info.component_kind) return bind_component_port(std::move(binding), port, value, context);
  if (info.direction != PortDirection::kInput) {
    return bind_entry_port(std::move(binding), port, value);
  }
  const bool is_template = info.type == std::type_index(typeid(TextTemplate));
  if (value.IsScalar() && !is_template) {
    if (auto entry = parse_reference(value.Scalar())) {
      binding.source = PortBinding::Source::kEntry;
      binding.key = *entry;
      return binding;
    }
    if (looks_like_reference(value.Scalar())) bad_reference(port, value.Scalar(), binding.where);
  }
  return bind_literal_port(std::move(binding), port, value, context);
}

PortBinding default_binding(const PortInfo& info, const SourceLocation& node_where,
                            const LiteralConverters& converters) {
  PortBinding binding;
  binding.info = info;
  binding.where = node_where;
  if (info.default_value.has_value()) {
    binding.source = PortBinding::Source::kDefault;
    binding.value = info.default_value;
  } else if (info.default_text) {
    if (auto entry = parse_reference(*info.default_text)) {
      binding.source = PortBinding::Source::kEntry;
      binding.key = *entry;
      return binding;
    }
    auto converted = converters.parse_text(info.type, *info.default_text);
    if (!converted) {
      throw Error("the default '" + *info.default_text + "' of port '" + info.name +
                      "' is not a valid " + info.type_name,
                  node_where);
    }
    binding.source = PortBinding::Source::kDefault;
    binding.value = std::move(*converted);
  }
  return binding;
}

}  // namespace antipode::bt::detail
