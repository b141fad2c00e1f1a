#include "dl_error.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>

namespace antipode::detail {

std::string readable_dl_error(const std::string& text) {
  const std::string marker = "undefined symbol: ";
  const auto at = text.find(marker);
  if (at == std::string::npos) return text;
  const auto begin = at + marker.size();
  auto end = text.find_first_of(" \t\n,", begin);
  if (end == std::string::npos) end = text.size();
  const std::string symbol = text.substr(begin, end - begin);
  if (symbol.rfind("_Z", 0) != 0) return text;
  int status = 0;
  const std::unique_ptr<char, decltype(&std::free)> readable(
      abi::__cxa_demangle(symbol.c_str(), nullptr, nullptr, &status), &std::free);
  if (status != 0 || readable == nullptr) return text;
  return text.substr(0, begin) + readable.get() + " [" + symbol + "]" + text.substr(end);
}

}  // namespace antipode::detail
