#include <nlohmann/json.hpp>

#include "antipode/bt/node.hpp"
#include "antipode/bt/tracers.hpp"
#include "antipode/core/error.hpp"

namespace antipode::bt {

JsonlTracer::JsonlTracer(const std::string& path)
    : path_(path),
      out_(path, std::ios::out | std::ios::trunc),
      start_(std::chrono::steady_clock::now()) {
  if (!out_) throw Error("cannot open trace file '" + path + "' for writing");
}

void JsonlTracer::on_status_change(const Node& node, Status previous, Status current,
                                   std::chrono::steady_clock::time_point when) {
  nlohmann::ordered_json line = {
      {"time_s", std::chrono::duration<double>(when - start_).count()},
      {"node", node.name()},
      {"type", node.type()},
      {"path", node.path()},
      {"where", node.where().str()},
      {"from", to_string(previous)},
      {"to", to_string(current)},
  };
  if (current == Status::kFailure && !node.failure_reason().empty()) {
    line["reason"] = node.failure_reason();
  }
  out_ << line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
  out_.flush();
  if (!out_) throw Error("cannot write trace file '" + path_ + "'");
}

}  // namespace antipode::bt
