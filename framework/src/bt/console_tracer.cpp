#include <cstdio>

#include "antipode/bt/node.hpp"
#include "antipode/bt/tracers.hpp"

namespace antipode::bt {
namespace {

const char* colour_of(Status status) {
  switch (status) {
    case Status::kRunning:
      return "\033[33m";
    case Status::kSuccess:
      return "\033[32m";
    case Status::kFailure:
      return "\033[31m";
    case Status::kIdle:
      return "\033[90m";
  }
  return "";
}

std::string label(const Node& node) {
  if (node.name().empty() || node.name() == node.type()) return node.type();
  return node.type() + "(" + node.name() + ")";
}

}  // namespace

ConsoleTracer::ConsoleTracer(std::ostream& out, bool colour)
    : out_(out), colour_(colour), start_(std::chrono::steady_clock::now()) {}

std::string ConsoleTracer::status_text(Status status) const {
  if (!colour_) return to_string(status);
  return std::string(colour_of(status)) + to_string(status) + "\033[0m";
}

void ConsoleTracer::on_status_change(const Node& node, Status previous, Status current,
                                     std::chrono::steady_clock::time_point when) {
  const double seconds = std::chrono::duration<double>(when - start_).count();
  char stamp[32];
  std::snprintf(stamp, sizeof(stamp), "[%7.3fs] ", seconds);
  out_ << stamp << label(node) << ' ' << status_text(previous) << " -> " << status_text(current);
  if (current == Status::kFailure && !node.failure_reason().empty()) {
    out_ << ": " << node.failure_reason();
  }
  if (current == Status::kIdle) out_ << " (halted)";
  out_ << '\n';
}

}  // namespace antipode::bt
