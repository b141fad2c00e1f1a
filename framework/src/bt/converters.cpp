#include "antipode/bt/converters.hpp"

#include <charconv>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "antipode/core/yaml_limits.hpp"

namespace antipode::bt {
namespace {

const std::string& scalar(const YAML::Node& value) {
  if (!value.IsScalar()) throw std::invalid_argument("not a scalar");
  return value.Scalar();
}

// Strict number parsing: the whole text must be the number (a leading '+' is allowed).
template <typename T>
T parse_number(const YAML::Node& value) {
  const std::string& text = scalar(value);
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  T result{};
  const auto [end, error] = std::from_chars(first, last, result);
  if (error != std::errc() || end != last || first == last) {
    throw std::invalid_argument("not a number");
  }
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(result)) throw std::invalid_argument("not a finite number");
  }
  return result;
}

bool parse_bool(const YAML::Node& value) {
  const std::string& text = scalar(value);
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  throw std::invalid_argument("not a bool");
}

std::chrono::milliseconds parse_msec(const YAML::Node& value) {
  const long count = parse_number<long>(value);
  // A bound keeps deadline arithmetic (now + duration, in nanoseconds) from overflowing.
  constexpr long kMaxMsec = 1000L * 1000 * 1000 * 1000;  // about 31 years
  if (count < 0) throw std::invalid_argument("negative duration");
  if (count > kMaxMsec) throw std::invalid_argument("duration over 10^12 ms");
  return std::chrono::milliseconds(count);
}

template <typename T>
std::vector<T> parse_list(const YAML::Node& value, T (*item)(const YAML::Node&)) {
  if (!value.IsSequence()) throw std::invalid_argument("not a list");
  std::vector<T> result;
  result.reserve(value.size());
  for (const auto& element : value) result.push_back(item(element));
  return result;
}

std::string parse_string(const YAML::Node& value) { return scalar(value); }

template <typename T>
std::string print_number(const T& value) {
  if constexpr (std::is_floating_point_v<T>) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return error == std::errc() ? std::string(buffer, end) : std::string("?");
  } else {
    return std::to_string(value);
  }
}

template <typename T>
std::string print_list(const std::vector<T>& values, std::string (*item)(const T&)) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ", ";
    text += item(values[i]);
  }
  return text + "]";
}

std::string print_string(const std::string& value) { return value; }

template <typename T>
void add_number(LiteralConverters& table) {
  table.add<T>(&parse_number<T>, &print_number<T>);
}

void add_builtins(LiteralConverters& table) {
  add_number<int>(table);
  add_number<long>(table);
  add_number<unsigned long>(table);
  add_number<unsigned>(table);
  add_number<double>(table);
  add_number<float>(table);
  table.add<bool>(&parse_bool, [](const bool& value) { return value ? "true" : "false"; });
  table.add<std::string>(&parse_string, &print_string);
  table.add<std::chrono::milliseconds>(&parse_msec, [](const std::chrono::milliseconds& value) {
    return std::to_string(value.count());
  });
  table.add<TextTemplate>([](const YAML::Node& value) { return TextTemplate{scalar(value)}; },
                          [](const TextTemplate& value) { return value.text; });
  // Ports of type std::any (SetBlackboard's value) take a scalar literal as text.
  table.add_erased(
      std::type_index(typeid(std::any)),
      [](const YAML::Node& value) { return std::any(scalar(value)); }, nullptr);
  table.add<std::vector<std::string>>(
      [](const YAML::Node& value) { return parse_list<std::string>(value, &parse_string); },
      [](const std::vector<std::string>& value) { return print_list(value, &print_string); });
  table.add<std::vector<double>>(
      [](const YAML::Node& value) { return parse_list<double>(value, &parse_number<double>); },
      [](const std::vector<double>& value) { return print_list(value, &print_number<double>); });
  table.add<std::vector<int>>(
      [](const YAML::Node& value) { return parse_list<int>(value, &parse_number<int>); },
      [](const std::vector<int>& value) { return print_list(value, &print_number<int>); });
}

}  // namespace

LiteralConverters::LiteralConverters() { add_builtins(*this); }

void LiteralConverters::add_erased(std::type_index type, Parse parse, Format format) {
  entries_.insert_or_assign(type, Entry{std::move(parse), std::move(format)});
}

bool LiteralConverters::can_parse(std::type_index type) const {
  const auto found = entries_.find(type);
  return found != entries_.end() && static_cast<bool>(found->second.parse);
}

std::optional<std::any> LiteralConverters::parse(std::type_index type,
                                                 const YAML::Node& value) const {
  const auto found = entries_.find(type);
  if (found == entries_.end() || !found->second.parse) return std::nullopt;
  try {
    return found->second.parse(value);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<std::any> LiteralConverters::parse_text(std::type_index type,
                                                      const std::string& text) const {
  if (type == std::type_index(typeid(std::string))) return std::any(text);
  YAML::Node as_yaml;
  try {
    as_yaml = YAML::Load(text);
  } catch (const YAML::Exception&) {
    as_yaml = YAML::Node(text);
  }
  check_yaml_size(as_yaml, "the value '" + text.substr(0, 40) + "'");
  if (!as_yaml.IsScalar()) {
    if (auto value = parse(type, as_yaml)) return value;
    as_yaml = YAML::Node(text);
  }
  return parse(type, as_yaml);
}

std::string LiteralConverters::format(const std::any& value) const {
  if (!value.has_value()) return "<empty>";
  const auto found = entries_.find(std::type_index(value.type()));
  if (found != entries_.end() && found->second.format) return found->second.format(value);
  return "<" + type_name(value.type()) + ">";
}

}  // namespace antipode::bt
