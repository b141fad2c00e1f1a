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

Status OrderedControl::tick() {
  while (current_ < child_count()) {
    const Status status = child(current_).execute_tick();
    if (status == Status::kRunning) return Status::kRunning;
    if (status != keep_going_) {
      halt();
      return status;
    }
    ++current_;
  }
  halt();
  return keep_going_;
}

void OrderedControl::halt() {
  current_ = 0;
  ControlNode::halt();
}

Status ReactiveControl::tick() {
  for (std::size_t i = 0; i < child_count(); ++i) {
    const Status status = child(i).execute_tick();
    if (status == Status::kRunning) {
      for (std::size_t other = 0; other < child_count(); ++other) {
        if (other != i) halt_child(other);
      }
      return Status::kRunning;
    }
    if (status != keep_going_) {
      halt_children();
      return status;
    }
  }
  halt_children();
  return keep_going_;
}

NodeManifest Sequence::manifest() {
  return control("Sequence",
                 "Ticks its children in order while they succeed; resumes a RUNNING child.");
}

NodeManifest ReactiveSequence::manifest() {
  return control("ReactiveSequence",
                 "Like Sequence, but re-ticks its children from the first on every tick.");
}

NodeManifest Fallback::manifest() {
  return control("Fallback",
                 "Ticks its children in order until one succeeds; resumes a RUNNING child.");
}

NodeManifest ReactiveFallback::manifest() {
  return control("ReactiveFallback",
                 "Like Fallback, but re-ticks its children from the first on every tick.");
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
