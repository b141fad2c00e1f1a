#include "view_trace.hpp"

#include <filesystem>
#include <fstream>
#include <map>

#include "antipode/core/error.hpp"
#include "view_encode.hpp"

namespace antipode::cli {
namespace {

using Json = nlohmann::ordered_json;

// The line's fields, checked: a status change as JsonlTracer writes it.
Json status_change(const std::string& text, const std::string& where) {
  Json line;
  try {
    line = Json::parse(text);
  } catch (const Json::exception& e) {
    throw Error(where + ": not JSON (" + e.what() + ")");
  }
  const auto is = [&](const char* key, bool (Json::*test)() const noexcept) {
    return line.is_object() && line.contains(key) && (line[key].*test)();
  };
  if (!is("time_s", &Json::is_number) || !is("path", &Json::is_string) ||
      !is("to", &Json::is_string))
    throw Error(where +
                ": not a status change (it needs \"time_s\", \"path\" and \"to\"; `antipode run "
                "--trace` writes them)");
  return line;
}

// The parent of each node: the longest proper prefix of its path, at a '/', that is a node.
void link_parents(Json& nodes, const std::map<std::string, int>& index) {
  for (Json& node : nodes) {
    std::string path = node["path"];
    int parent = -1;
    for (auto cut = path.rfind('/'); cut != std::string::npos && parent < 0;
         cut = cut == 0 ? std::string::npos : path.rfind('/', cut - 1)) {
      const auto found = index.find(path.substr(0, cut));
      if (found != index.end()) parent = found->second;
    }
    node["parent"] = parent;
  }
}

}  // namespace

Json trace_json(const std::string& path) {
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path))
    throw Error(path + ": cannot read the trace (write one with `antipode run TREE --trace FILE`)");
  Json nodes = Json::array(), statuses = Json::array(), reasons = Json::array(),
       events = Json::array();
  std::map<std::string, int> node_index, status_index, reason_index;
  std::string text;
  for (std::size_t number = 1; std::getline(in, text); ++number) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const Json line = status_change(text, path + ":" + std::to_string(number));
    const std::string node_path = line["path"];
    if (node_index.find(node_path) == node_index.end()) {
      node_index.emplace(node_path, int(nodes.size()));
      nodes.push_back({{"path", node_path},
                       {"name", line.value("node", node_path)},
                       {"type", line.value("type", "")},
                       {"where", line.value("where", "")}});
    }
    const std::string reason = line.value("reason", "");
    const std::string from =
        line.contains("from") && line["from"].is_string() ? line["from"] : "IDLE";
    events.push_back({line["time_s"], node_index[node_path],
                      name_index(from, statuses, status_index),
                      name_index(line["to"], statuses, status_index),
                      reason.empty() ? -1 : name_index(reason, reasons, reason_index)});
  }
  if (events.empty()) throw Error(path + ": the trace holds no status change");
  link_parents(nodes, node_index);
  return {{"file", std::filesystem::path(path).filename().string()},
          {"nodes", nodes},
          {"statuses", statuses},
          {"events", events},
          {"reasons", reasons}};
}

}  // namespace antipode::cli
