#include "control_nodes.hpp"

namespace antipode::bt::builtin {
namespace {

NodeManifest control(std::string type, std::string summary, std::vector<PortInfo> ports = {}) {
  NodeManifest manifest;
  manifest.type = std::move(type);
  manifest.category = NodeCategory::kControl;
  manifest.ports = std::move(ports);
  manifest.min_children = 1;
  manifest.max_children = -1;
  manifest.summary = std::move(summary);
  return manifest;
}

}  // namespace

NodeManifest Sequence::manifest() {
  return control("Sequence",
                 "Ticks its children in order while they succeed; resumes a RUNNING child.");
}

Status Sequence::tick() {
  while (current_ < child_count()) {
    const Status status = child(current_).execute_tick();
    if (status == Status::kRunning) return Status::kRunning;
    if (status == Status::kFailure) {
      halt();
      return Status::kFailure;
    }
    ++current_;
  }
  halt();
  return Status::kSuccess;
}

void Sequence::halt() {
  current_ = 0;
  ControlNode::halt();
}

NodeManifest ReactiveSequence::manifest() {
  return control("ReactiveSequence",
                 "Like Sequence, but re-ticks its children from the first on every tick.");
}

Status ReactiveSequence::tick() {
  for (std::size_t i = 0; i < child_count(); ++i) {
    const Status status = child(i).execute_tick();
    if (status == Status::kRunning) {
      for (std::size_t other = 0; other < child_count(); ++other) {
        if (other != i) halt_child(other);
      }
      return Status::kRunning;
    }
    if (status == Status::kFailure) {
      halt_children();
      return Status::kFailure;
    }
  }
  halt_children();
  return Status::kSuccess;
}

NodeManifest Fallback::manifest() {
  return control("Fallback",
                 "Ticks its children in order until one succeeds; resumes a RUNNING child.");
}

Status Fallback::tick() {
  while (current_ < child_count()) {
    const Status status = child(current_).execute_tick();
    if (status == Status::kRunning) return Status::kRunning;
    if (status == Status::kSuccess) {
      halt();
      return Status::kSuccess;
    }
    ++current_;
  }
  halt();
  return Status::kFailure;
}

void Fallback::halt() {
  current_ = 0;
  ControlNode::halt();
}

NodeManifest ReactiveFallback::manifest() {
  return control("ReactiveFallback",
                 "Like Fallback, but re-ticks its children from the first on every tick.");
}

Status ReactiveFallback::tick() {
  for (std::size_t i = 0; i < child_count(); ++i) {
    const Status status = child(i).execute_tick();
    if (status == Status::kRunning) {
      for (std::size_t other = 0; other < child_count(); ++other) {
        if (other != i) halt_child(other);
      }
      return Status::kRunning;
    }
    if (status == Status::kSuccess) {
      halt_children();
      return Status::kSuccess;
    }
  }
  halt_children();
  return Status::kFailure;
}

NodeManifest Parallel::manifest() {
  return control(
      "Parallel", "Ticks all children each tick until enough succeed or enough fail.",
      {input_port<int>("success_count", -1,
                       "successes needed to succeed; -1 = all children, -2 = all but one, ..."),
       input_port<int>("failure_count", 1,
                       "failures that make it fail; -1 = all children, -2 = all but one, ...")});
}

int Parallel::threshold(const std::string& port) const {
  const int n = static_cast<int>(child_count());
  const int given = get_input<int>(port);
  const int count = given < 0 ? n + given + 1 : given;
  if (count < 1 || count > n) {
    fail(port, "port '" + port + "' of " + describe() + " is " + std::to_string(given) +
                   ", which does not fit its " + std::to_string(n) + " children");
  }
  return count;
}

Status Parallel::tick() {
  const int n = static_cast<int>(child_count());
  const int need_successes = threshold("success_count");
  const int max_failures = threshold("failure_count");
  for (std::size_t i = 0; i < child_count(); ++i) {
    if (completed_.count(i) != 0) continue;
    const Status status = child(i).execute_tick();
    if (status == Status::kRunning) continue;
    completed_.insert(i);
    (status == Status::kSuccess ? successes_ : failures_) += 1;
    if (successes_ >= need_successes) return finish(Status::kSuccess);
    if (failures_ >= max_failures || n - failures_ < need_successes) {
      return finish(Status::kFailure);
    }
  }
  return Status::kRunning;
}

Status Parallel::finish(Status result) {
  halt();
  return result;
}

void Parallel::halt() {
  completed_.clear();
  successes_ = 0;
  failures_ = 0;
  ControlNode::halt();
}

}  // namespace antipode::bt::builtin
