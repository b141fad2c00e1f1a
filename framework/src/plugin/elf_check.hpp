#pragma once
// A plugin library's ELF file checked before dlopen maps it: a file cut short (an interrupted
// copy or build) would be mapped past its end, and the first touch of the missing part kills
// the process with SIGBUS instead of giving an error.

#include <string>

namespace antipode::detail {

/// "" when `path` is a 64-bit ELF file whose program headers and loadable segments all lie
/// within the file; otherwise why not ("the file is truncated: segment 2 ends at byte 48,112
/// of 20,000"). Files that are not 64-bit ELF are left to dlopen's own message.
std::string elf_problem(const std::string& path);

}  // namespace antipode::detail
