#pragma once
// Test helper: the message of the antipode::Error a call throws.

#include <string>

#include "antipode/core/error.hpp"

namespace antipode::testing {

/// what() of the antipode::Error that `call()` throws, or "" when it throws none.
template <typename Call>
std::string error_of(Call&& call) {
  try {
    call();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

}  // namespace antipode::testing
