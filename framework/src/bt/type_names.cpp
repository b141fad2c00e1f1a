#include <cxxabi.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/converters.hpp"

namespace antipode::bt {
namespace {

const std::map<std::type_index, std::string>& known_names() {
  static const std::map<std::type_index, std::string> names = {
      {typeid(bool), "bool"},
      {typeid(int), "int"},
      {typeid(long), "int64"},
      {typeid(unsigned long), "uint64"},
      {typeid(unsigned), "unsigned"},
      {typeid(double), "double"},
      {typeid(float), "float"},
      {typeid(std::string), "string"},
      {typeid(std::vector<std::string>), "list of string"},
      {typeid(std::vector<double>), "list of double"},
      {typeid(std::vector<int>), "list of int"},
      {typeid(std::chrono::milliseconds), "milliseconds"},
      {typeid(TextTemplate), "text"},
      {typeid(std::any), "any"},
  };
  return names;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

std::string demangle(const char* mangled) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> name(
      abi::__cxa_demangle(mangled, nullptr, nullptr, &status), std::free);
  std::string text = (status == 0 && name) ? name.get() : mangled;
  replace_all(text, "std::__cxx11::", "std::");
  replace_all(text, "std::basic_string<char, std::char_traits<char>, std::allocator<char> >",
              "std::string");
  return text;
}

}  // namespace

std::string type_name(std::type_index type) {
  const auto& names = known_names();
  const auto found = names.find(type);
  return found != names.end() ? found->second : demangle(type.name());
}

std::string describe_yaml(const YAML::Node& value) {
  if (!value.IsDefined() || value.IsNull()) return "nothing";
  if (value.IsScalar()) return value.Scalar();
  if (value.IsSequence()) return "a list";
  return "a mapping";
}

}  // namespace antipode::bt
