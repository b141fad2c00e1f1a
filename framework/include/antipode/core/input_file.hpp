#pragma once
/// @file
/// Checking an input path before reading it: a folder has no bytes to read, and a FIFO or a
/// device may block forever or never end.

#include <string>

namespace antipode {

/// Throws antipode::Error "PATH: not a regular file (a folder): give WHAT" (or "(a device or
/// FIFO)"), `what` saying what is expected ("a tree file"), when `path` exists and is not a
/// regular file (symbolic links are followed). A missing path passes: the reader's own
/// "cannot open" error names it.
void require_regular_file(const std::string& path, const std::string& what);

}  // namespace antipode
