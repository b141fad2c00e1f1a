#pragma once
// Internal to the plugin area: dlopen's error text made readable.

#include <string>

namespace antipode::detail {

/// `text` (dlerror()'s) with a mangled C++ symbol after "undefined symbol: " shown
/// demangled, the mangled name kept in brackets: "undefined symbol:
/// antipode::Cloud::validate() const [_ZNK8antipode5Cloud8validateEv]". Other text is
/// returned as it is.
std::string readable_dl_error(const std::string& text);

}  // namespace antipode::detail
