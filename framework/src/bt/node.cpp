#include "antipode/bt/node.hpp"

#include <iostream>
#include <typeindex>
#include <typeinfo>

#include "antipode/bt/converters.hpp"
#include "tree_context.hpp"

namespace antipode::bt {
namespace {

const std::type_index kAnyType(typeid(std::any));
const std::type_index kStringType(typeid(std::string));

// FNV-1a: a stable 64-bit hash of a node path, used to derive the node's random stream.
std::uint64_t hash_path(const std::string& path) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : path) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::string port_of(const std::string& port, const Node& node) {
  return "port '" + port + "' of " + node.describe();
}

}  // namespace

Node::Node(const NodeConfig& config) : config_(config) {}

Node::~Node() = default;

Status Node::execute_tick() {
  const Status previous = status_;
  starting_ = previous != Status::kRunning;
  if (starting_) {
    ++run_count_;
    failure_reason_.clear();
    // As in BehaviorTree.CPP, a control node or decorator is RUNNING while its children
    // tick, so traces show the parent start before its children.
    if (!children_.empty()) set_status(Status::kRunning);
  }
  Status result = Status::kIdle;
  try {
    result = tick();
    if (result == Status::kIdle) throw Error(describe() + " returned IDLE from its tick", where());
    if (result == Status::kRunning && !may_return_running()) {
      throw Error(describe() + " is synchronous but returned RUNNING", where());
    }
  } catch (const Cancelled& e) {
    // A call stopped by stop_token() is a failure of this node, not an error of the run.
    abandon(previous);
    failure_reason_ = e.message();
    result = Status::kFailure;
  } catch (const Error&) {
    abandon(previous);
    rethrow_located();
  } catch (const std::exception& fault) {
    abandon(previous);
    failure_reason_ = plugin_fault(fault);
    result = Status::kFailure;
  } catch (...) {
    abandon(previous);
    rethrow_located();
  }
  set_status(result);
  return result;
}

std::string Node::plugin_fault(const std::exception& fault) const {
  std::string components;
  for (const auto& [port, bound] : config_.ports) {
    const auto* name = std::any_cast<std::string>(&bound.value);
    if (!bound.info.component_kind || name == nullptr || !config_.context) continue;
    const auto plugin = config_.context->component_plugins.find(*name);
    if (plugin == config_.context->component_plugins.end()) continue;
    components += std::string(components.empty() ? "" : ", ") +
                  to_string(*bound.info.component_kind) + " '" + *name + "' (plugin " +
                  plugin->second + ")";
  }
  return type() + "'s code" + (components.empty() ? "" : " or its " + components) + " threw " +
         type_name(std::type_index(typeid(fault))) + ": " + fault.what();
}

void Node::abandon(Status previous) noexcept {
  try {
    if (previous == Status::kRunning || !children_.empty()) halt();
  } catch (...) {
    // The error being propagated matters more than one from halting.
  }
  try {
    set_status(Status::kIdle);
  } catch (...) {
    // An observer failing here must not replace the error being propagated.
  }
}

void Node::rethrow_located() const { rethrow_with_context(describe(), where()); }

void Node::halt_node() {
  if (status_ == Status::kRunning) halt();
  set_status(Status::kIdle);
}

void Node::set_status(Status status) {
  const Status previous = status_;
  if (previous == status) return;
  status_ = status;
  if (status == Status::kIdle && previous != Status::kRunning) return;
  if (config_.context) config_.context->notify(*this, previous, status);
}

std::string Node::describe() const {
  if (config_.name.empty() || config_.name == config_.type) return config_.type;
  return config_.type + " '" + config_.name + "'";
}

const Node& Node::child_node(std::size_t index) const { return child(index); }

Node& Node::child(std::size_t index) const {
  if (index >= children_.size()) {
    throw Error(describe() + " has no child " + std::to_string(index), where());
  }
  return *children_[index];
}

std::vector<Node*> Node::children() const {
  std::vector<Node*> result;
  result.reserve(children_.size());
  for (const auto& node : children_) result.push_back(node.get());
  return result;
}

void Node::halt_child(std::size_t index) { child(index).halt_node(); }

void Node::halt_children(std::size_t first) {
  for (std::size_t i = first; i < children_.size(); ++i) children_[i]->halt_node();
}

const PortBinding& Node::binding(const std::string& port) const {
  const auto found = config_.ports.find(port);
  if (found != config_.ports.end()) return found->second;
  std::vector<std::string> names;
  for (const auto& [name, bound] : config_.ports) names.push_back(name);
  throw Error(describe() + " has no port '" + port + "'" + did_you_mean(port, names), where());
}

void Node::fail(const std::string& port, const std::string& message) const {
  const auto found = config_.ports.find(port);
  if (found != config_.ports.end() && found->second.where.known()) {
    throw Error(message, found->second.where);
  }
  throw Error(message, where());
}

const std::any& Node::input_value(const std::string& port, std::type_index type,
                                  std::any& scratch) const {
  const PortBinding& bound = binding(port);
  if (bound.info.direction == PortDirection::kOutput) {
    fail(port, port_of(port, *this) + " is an output and cannot be read");
  }
  switch (bound.source) {
    case PortBinding::Source::kUnset:
      fail(port, port_of(port, *this) + " has no value");
    case PortBinding::Source::kEntry:
      return entry_value(bound, type, scratch);
    case PortBinding::Source::kLiteral:
    case PortBinding::Source::kDefault:
      break;
  }
  if (type == kAnyType || std::type_index(bound.value.type()) == type) return bound.value;
  const auto& converters = blackboard().converters();
  std::optional<std::any> converted;
  if (bound.source == PortBinding::Source::kLiteral) {
    converted = converters.parse(type, bound.literal);
  } else if (bound.info.default_text) {
    converted = converters.parse_text(type, *bound.info.default_text);
  }
  if (!converted) {
    fail(port, port_of(port, *this) + " holds " + type_name(bound.value.type()) +
                   ", which cannot be read as " + type_name(type));
  }
  scratch = std::move(*converted);
  return scratch;
}

const std::any& Node::entry_value(const PortBinding& bound, std::type_index type,
                                  std::any& scratch) const {
  const std::string reads = port_of(bound.info.name, *this) + " reads {" + bound.key + "}";
  const std::any* value = blackboard().find(bound.key);
  if (value == nullptr) throw Error(reads + ", which no node has written yet", bound.where);
  const std::type_index held(value->type());
  if (type == kAnyType || held == type) return *value;
  if (held == kStringType && blackboard().converters().can_parse(type)) {
    const auto& text = std::any_cast<const std::string&>(*value);
    auto converted = blackboard().converters().parse_text(type, text);
    if (!converted) {
      throw Error(reads + " as " + type_name(type) + ", but it holds the text '" + text + "'",
                  bound.where);
    }
    scratch = std::move(*converted);
    return scratch;
  }
  throw Error(reads + " as " + type_name(type) + ", but it holds " + type_name(held), bound.where);
}

void Node::write_output(const std::string& port, std::any value) {
  const PortBinding& bound = binding(port);
  if (bound.info.direction == PortDirection::kInput) {
    fail(port, port_of(port, *this) + " is an input and cannot be written");
  }
  const std::type_index declared = bound.info.type;
  if (declared != kAnyType && declared != std::type_index(value.type())) {
    fail(port, port_of(port, *this) + " is declared as " + bound.info.type_name +
                   " but was written a " + type_name(value.type()));
  }
  if (bound.source != PortBinding::Source::kEntry) return;
  try {
    blackboard().set_any(bound.key, std::move(value));
  } catch (const Error& error) {
    throw Error(port_of(port, *this) + " cannot write {" + bound.key + "}: " + error.message(),
                bound.where);
  }
}

Component& Node::component_base(const std::string& port, ComponentKind kind) const {
  const PortBinding& bound = binding(port);
  if (!bound.info.component_kind) fail(port, port_of(port, *this) + " is not a component port");
  const auto* name = std::any_cast<std::string>(&bound.value);
  std::shared_ptr<Component> found;
  if (name != nullptr && config_.context) {
    const auto entry = config_.context->components.find(*name);
    if (entry != config_.context->components.end()) found = entry->second;
  }
  if (!found) fail(port, port_of(port, *this) + " names no loaded component");
  if (found->kind() != kind) {
    fail(port, port_of(port, *this) + " names a " + to_string(found->kind()) +
                   " component, not a " + to_string(kind));
  }
  return *found;
}

std::string Node::expand(const TextTemplate& text) const {
  std::string result;
  const std::string& source = text.text;
  std::size_t at = 0;
  while (at < source.size()) {
    const auto open = source.find('{', at);
    const auto close = open == std::string::npos ? open : source.find('}', open);
    if (close == std::string::npos) break;
    const std::string key = source.substr(open + 1, close - open - 1);
    result += source.substr(at, open - at);
    result += is_valid_key(key) ? blackboard().text(key) : source.substr(open, close - open + 1);
    at = close + 1;
  }
  if (at < source.size()) result += source.substr(at);
  return result;
}

RandomStream Node::random() const {
  const std::uint64_t seed = config_.context ? config_.context->seed : 0;
  return RandomStream(seed).derive(hash_path(config_.path)).derive(run_count_);
}

StopToken Node::stop_token() const { return config_.context ? config_.context->stop : StopToken(); }

void Node::progress(std::size_t done, std::size_t total, const std::string& what) const {
  if (config_.context && config_.context->progress_sink) {
    config_.context->progress_sink(*this, done, total, what);
  }
}

void Node::log(const std::string& message) const {
  if (config_.context && config_.context->log_sink) {
    config_.context->log_sink(*this, message);
  } else {
    std::cout << message << '\n';
  }
}

}  // namespace antipode::bt
