#pragma once
// `antipode view` of a tree run's trace (`antipode run --trace`, bt::JsonlTracer): the tree
// as the page draws it, and every status change to step through.

#include <string>

#include <nlohmann/json.hpp>

namespace antipode::cli {

/// The trace in `path` as {"file", "nodes": [{"path", "name", "type", "where", "parent"}],
/// "statuses": [names], "events": [[time_s, node, from status, to status, reason index or -1]],
/// "reasons": [texts]}. A node's parent is the node whose path is the longest proper prefix of its
/// own
/// (-1 for the root); nodes come in the order they first changed status. Throws
/// antipode::Error "PATH:LINE: ..." for a line that is not a status change, and for a file
/// with none.
nlohmann::ordered_json trace_json(const std::string& path);

}  // namespace antipode::cli
