#include "leaf_nodes.hpp"

#include <any>

#include "tree_context.hpp"

namespace antipode::bt::builtin {
namespace {

NodeManifest action(std::string type, std::string summary, std::vector<PortInfo> ports = {}) {
  NodeManifest manifest;
  manifest.type = std::move(type);
  manifest.category = NodeCategory::kAction;
  manifest.ports = std::move(ports);
  manifest.summary = std::move(summary);
  return manifest;
}

}  // namespace

NodeManifest AlwaysSuccess::manifest() { return action("AlwaysSuccess", "Succeeds."); }

NodeManifest AlwaysFailure::manifest() { return action("AlwaysFailure", "Fails."); }

NodeManifest SetBlackboard::manifest() {
  return action("SetBlackboard", "Writes a value to a blackboard entry.",
                {output_port<std::any>("key", "the entry to write"),
                 input_port<std::any>("value", "a literal (stored as text) or {entry} to copy"),
                 input_port<bool>("if_unset", false,
                                  "write only when the entry does not exist yet: a default "
                                  "that --set key=value overrides")});
}

Status SetBlackboard::tick() {
  if (get_input<bool>("if_unset")) {
    const PortBinding& key = detail::NodeAccess::binding(*this, "key");
    if (key.source == PortBinding::Source::kEntry && blackboard().has(key.key))
      return Status::kSuccess;
  }
  set_output("key", get_input<std::any>("value"));
  return Status::kSuccess;
}

NodeManifest Log::manifest() {
  return action("Log", "Sends a message to the tree's log (stdout by default).",
                {input_port<TextTemplate>("message", "text; {key} prints an entry's value")});
}

Status Log::tick() {
  log(expand(get_input<TextTemplate>("message")));
  return Status::kSuccess;
}

NodeManifest Wait::manifest() {
  return action("Wait", "RUNNING for msec milliseconds, then SUCCESS.",
                {input_port<std::chrono::milliseconds>("msec", "how long to wait")});
}

Status Wait::on_start() {
  const auto duration = get_input<std::chrono::milliseconds>("msec");
  deadline_ = std::chrono::steady_clock::now() + duration;
  return duration.count() == 0 ? Status::kSuccess : Status::kRunning;
}

Status Wait::on_running() {
  return std::chrono::steady_clock::now() >= deadline_ ? Status::kSuccess : Status::kRunning;
}

}  // namespace antipode::bt::builtin
