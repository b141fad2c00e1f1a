#include "decorator_nodes.hpp"

#include "tree_context.hpp"

namespace antipode::bt::builtin {
namespace {

NodeManifest decorator(std::string type, std::string summary, std::vector<PortInfo> ports = {}) {
  NodeManifest manifest;
  manifest.type = std::move(type);
  manifest.category = NodeCategory::kDecorator;
  manifest.ports = std::move(ports);
  manifest.min_children = 1;
  manifest.max_children = 1;
  manifest.summary = std::move(summary);
  return manifest;
}

}  // namespace

NodeManifest Inverter::manifest() {
  return decorator("Inverter", "Turns its child's SUCCESS into FAILURE and back.");
}

Status Inverter::tick() {
  const Status status = child().execute_tick();
  if (status == Status::kRunning) return status;
  halt_child(0);
  return status == Status::kSuccess ? Status::kFailure : Status::kSuccess;
}

NodeManifest ForceSuccess::manifest() {
  return decorator("ForceSuccess", "Succeeds whenever its child completes.");
}

Status ForceSuccess::tick() {
  const Status status = child().execute_tick();
  if (status == Status::kRunning) return status;
  halt_child(0);
  return Status::kSuccess;
}

NodeManifest ForceFailure::manifest() {
  return decorator("ForceFailure", "Fails whenever its child completes.");
}

Status ForceFailure::tick() {
  const Status status = child().execute_tick();
  if (status == Status::kRunning) return status;
  halt_child(0);
  return Status::kFailure;
}

NodeManifest Retry::manifest() {
  return decorator("Retry", "Re-runs a failing child up to num_attempts times.",
                   {input_port<int>("num_attempts",
                                    "how many times the child may run; -1 = until it succeeds")});
}

Status Retry::tick() {
  const int attempts = get_input<int>("num_attempts");
  if (attempts < -1)
    fail("num_attempts", "port 'num_attempts' of " + describe() + " must be -1 or more");
  while (attempts == -1 || failed_attempts_ < attempts) {
    const Status status = child().execute_tick();
    if (status == Status::kRunning) return status;
    halt_child(0);
    if (status == Status::kSuccess) {
      failed_attempts_ = 0;
      return Status::kSuccess;
    }
    ++failed_attempts_;
    if (attempts == -1) return Status::kRunning;  // unbounded: let the tree breathe
  }
  set_failure_reason("failed " + std::to_string(failed_attempts_) + " attempts");
  failed_attempts_ = 0;
  return Status::kFailure;
}

void Retry::halt() {
  failed_attempts_ = 0;
  DecoratorNode::halt();
}

NodeManifest Repeat::manifest() {
  return decorator(
      "Repeat", "Runs its child num_cycles times while it succeeds.",
      {input_port<int>("num_cycles", "how many successful runs; -1 = forever"),
       input_port<std::string>("progress", std::string{},
                               "a label: report each finished run as progress of this")});
}

Status Repeat::tick() {
  const int cycles = get_input<int>("num_cycles");
  if (cycles < -1) fail("num_cycles", "port 'num_cycles' of " + describe() + " must be -1 or more");
  while (cycles == -1 || cycles_ < cycles) {
    const Status status = child().execute_tick();
    if (status == Status::kRunning) return status;
    halt_child(0);
    if (status == Status::kFailure) {
      cycles_ = 0;
      return Status::kFailure;
    }
    ++cycles_;
    report_progress(cycles);
    if (cycles == -1) return Status::kRunning;  // unbounded: let the tree breathe
  }
  cycles_ = 0;
  return Status::kSuccess;
}

void Repeat::report_progress(int cycles) const {
  if (cycles <= 0) return;
  const auto label = get_input<std::string>("progress");
  if (!label.empty()) {
    progress(static_cast<std::size_t>(cycles_), static_cast<std::size_t>(cycles), label);
  }
}

void Repeat::halt() {
  cycles_ = 0;
  DecoratorNode::halt();
}

NodeManifest KeepRunningUntilFailure::manifest(const std::string& type) {
  return decorator(type,
                   "Re-runs its child while it succeeds (RUNNING meanwhile); fails when "
                   "the child fails.");
}

Status KeepRunningUntilFailure::tick() {
  const Status status = child().execute_tick();
  if (status == Status::kRunning) return status;
  halt_child(0);
  return status == Status::kSuccess ? Status::kRunning : Status::kFailure;
}

NodeManifest Timeout::manifest() {
  return decorator("Timeout", "Halts its child and fails when the child runs longer than msec.",
                   {input_port<std::chrono::milliseconds>("msec", "time limit in milliseconds")});
}

Status Timeout::tick() {
  const auto now = std::chrono::steady_clock::now();
  if (starting()) {
    limit_ = get_input<std::chrono::milliseconds>("msec");
    deadline_ = now + limit_;
  }
  if (now >= deadline_) return expire();
  const Status status = tick_child_with_deadline();
  if (status != Status::kRunning) {
    halt_child(0);
    return status;
  }
  return std::chrono::steady_clock::now() >= deadline_ ? expire() : Status::kRunning;
}

// The child's calls see the deadline through Node::stop_token(), so a long plugin call
// (a plan, a classification) inside one tick returns once it passes.
Status Timeout::tick_child_with_deadline() {
  detail::TreeContext* context = detail::NodeAccess::context(*this);
  if (context == nullptr) return child().execute_tick();
  struct Restore {
    detail::TreeContext& context;
    StopToken saved;
    ~Restore() { context.stop = std::move(saved); }
  } restore{*context, context->stop};
  context->stop = restore.saved.with_deadline(deadline_);
  return child().execute_tick();
}

Status Timeout::expire() {
  halt_child(0);
  set_failure_reason("timed out after " + std::to_string(limit_.count()) + " ms");
  return Status::kFailure;
}

NodeManifest SubTree::manifest() {
  NodeManifest manifest;
  manifest.type = "SubTree";
  manifest.category = NodeCategory::kSubTree;
  manifest.ports = {input_port<std::string>("tree", "the name of the tree to run")};
  manifest.min_children = 1;
  manifest.max_children = 1;
  manifest.summary =
      "Runs another tree of the file with its own blackboard, connected through `ports`.";
  return manifest;
}

Status SubTree::tick() {
  const Status status = child().execute_tick();
  if (status != Status::kRunning) halt_child(0);
  return status;
}

}  // namespace antipode::bt::builtin
