#pragma once
// Reading a JSON file a user names (a bench report, a shard, a trial record) within bounds:
// nlohmann's parser is not recursive, but copying or comparing what it built is, so a file
// nested a million levels deep would overflow the stack after parsing.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::evaluation {

/// The deepest nesting of arrays and objects a JSON input may have; antipode's own reports
/// nest 6 levels at most.
inline constexpr int kMaxJsonDepth = 100;

/// The JSON document in `path`. Throws antipode::Error "PATH: cannot read WHAT" (missing, a
/// folder, unreadable), "PATH: not JSON (REASON)" or "PATH: nested deeper than 100 levels",
/// where `what` says what the file should be ("the bench report").
nlohmann::ordered_json read_json_file(const std::string& path, const std::string& what);

}  // namespace antipode::evaluation
