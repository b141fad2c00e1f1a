#pragma once
/// @file
/// Conversion of YAML literals (and of text blackboard entries) to typed port values, and
/// readable names of C++ types for messages.
///
/// The table is keyed by std::type_index. It knows the common types out of the box; a plugin
/// that declares ports of its own types adds a parser for them through
/// NodeRegistry::converters() so that such ports accept literals in the YAML file.

#include <any>
#include <functional>
#include <optional>
#include <string>
#include <typeindex>
#include <unordered_map>

#include <yaml-cpp/yaml.h>

namespace antipode::bt {

/// The type of a port whose text may mention blackboard entries as `{key}`, replaced by the
/// entries' printed values when the port is read (e.g. Log's `message`). A port of this type
/// never names an entry as a whole, so `"{cloud}"` is a template, not a reference.
struct TextTemplate {
  std::string text;
};

/// A readable name of `type` for messages: "int", "int64", "uint64", "double", "bool",
/// "string", "list of string", "milliseconds", "text", "any", ... for the common types and
/// the demangled C++ name otherwise (e.g. "antipode::HandSet").
std::string type_name(std::type_index type);

template <typename T>
std::string type_name() {
  return type_name(std::type_index(typeid(T)));
}

/// How a YAML value is described in messages: its text for a scalar, "a list", "a mapping"
/// or "nothing".
std::string describe_yaml(const YAML::Node& value);

/// The converter table: YAML literal -> typed value, typed value -> text.
///
/// Built-in types: bool (true/false), int, long (int64), unsigned long (uint64), unsigned,
/// double, float, std::string, std::vector<std::string>, std::vector<double>,
/// std::vector<int> (YAML sequences), std::chrono::milliseconds (a non-negative integer) and
/// TextTemplate. Numbers are parsed strictly: "3.5" is not an int and "12abc" is nothing.
class LiteralConverters {
 public:
  /// Returns the converted value; throws any std::exception when the literal is unusable.
  using Parse = std::function<std::any(const YAML::Node& value)>;
  /// Prints a value known to hold the table entry's type.
  using Format = std::function<std::string(const std::any& value)>;

  /// A table holding the built-in types.
  LiteralConverters();

  /// Adds (or replaces) the converter for T. `format` may be null: values then print as
  /// "<type name>".
  template <typename T>
  void add(std::function<T(const YAML::Node&)> parse,
           std::function<std::string(const T&)> format = nullptr) {
    Format erased_format;
    if (format) {
      erased_format = [format](const std::any& value) {
        return format(std::any_cast<const T&>(value));
      };
    }
    add_erased(
        std::type_index(typeid(T)),
        [parse](const YAML::Node& value) { return std::any(parse(value)); },
        std::move(erased_format));
  }

  void add_erased(std::type_index type, Parse parse, Format format);

  /// True when literals of `type` can be converted.
  bool can_parse(std::type_index type) const;

  /// `value` converted to `type`, or nullopt when the type is unknown or the literal bad.
  std::optional<std::any> parse(std::type_index type, const YAML::Node& value) const;

  /// Text (e.g. a `--set` value or a string blackboard entry) converted to `type`: the text
  /// is read as YAML, so "[a, b]" gives a list and "42" a number.
  std::optional<std::any> parse_text(std::type_index type, const std::string& text) const;

  /// `value` printed for logs: registered types by their formatter, strings verbatim, others
  /// as "<type name>", an empty value as "<empty>".
  std::string format(const std::any& value) const;

 private:
  struct Entry {
    Parse parse;
    Format format;
  };
  std::unordered_map<std::type_index, Entry> entries_;
};

}  // namespace antipode::bt
