#pragma once
/// @file
/// Node: the base class of every behaviour-tree node, and NodeConfig, what the loader hands a
/// node's constructor.
///
/// A node type derives from one of the convenience bases (action_node.hpp, control_node.hpp,
/// decorator_node.hpp), declares its ports in a static `manifest()` and implements tick().
/// Inside tick() it reads inputs with get_input<T>(), writes outputs with set_output(), and
/// uses components with component<C>() (from docs/examples/sample_few_hands.cpp):
/// @code
///   Status tick() override {
///     const auto cloud = get_input<CloudPtr>("cloud");
///     auto hands = std::make_shared<HandSet>(
///         component<Sampler>("sampler").sample(*cloud, random(), stop_token()));
///     if (hands->hands.empty()) {
///       set_failure_reason("no hand hypotheses");
///       return Status::kFailure;
///     }
///     ...
///     set_output("hands", HandSetPtr(std::move(hands)));
///     return Status::kSuccess;
///   }
/// @endcode

#include <any>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <typeindex>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "antipode/bt/blackboard.hpp"
#include "antipode/bt/ports.hpp"
#include "antipode/bt/status.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/random.hpp"
#include "antipode/core/stop_token.hpp"

namespace antipode::bt {

namespace detail {
struct TreeContext;
struct NodeAccess;
}  // namespace detail

/// How one port of one node instance gets its value.
struct PortBinding {
  enum class Source {
    kUnset,    ///< not given and no default (an unconnected output)
    kLiteral,  ///< a literal in the YAML
    kDefault,  ///< the port's default
    kEntry,    ///< a blackboard entry
  };
  PortInfo info;
  Source source = Source::kUnset;
  std::string key;       ///< the blackboard key (kEntry)
  std::any value;        ///< the converted literal or default (kLiteral, kDefault)
  YAML::Node literal;    ///< the literal as written (kLiteral)
  SourceLocation where;  ///< where the value is written (the node's position for defaults)
};

/// Everything a node's constructor receives. Made by the loader; node types pass it on to
/// their base class unchanged.
struct NodeConfig {
  std::string type;      ///< the node type, e.g. "Sequence"
  std::string name;      ///< the YAML `name:`, or the type (SubTree: the tree's name)
  std::string path;      ///< unique in the tree, e.g. "detect/Sequence/SampleHands#1"
  SourceLocation where;  ///< the node's key in the YAML file
  NodeCategory category = NodeCategory::kAction;
  std::map<std::string, PortBinding> ports;  ///< every declared port of the type
  std::shared_ptr<Blackboard> blackboard;    ///< of the tree instance the node is in
  std::shared_ptr<detail::TreeContext> context;
};

class Node {
 public:
  explicit Node(const NodeConfig& config);
  virtual ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  /// Ticks the node: calls tick(), records the status and reports a change to the tree's
  /// observers. An antipode::Error without a location thrown by tick() is rethrown as an
  /// Error located at this node (an InternalError stays internal), after halting what the
  /// tick may have left RUNNING (the node is then IDLE). Any other std::exception is a fault
  /// of plugin code - the node's or a component's it called - and fails the node: the reason
  /// names the exception and the components the node uses with their plugins.
  Status execute_tick();

  /// Calls halt() if the node is RUNNING, then resets it to IDLE.
  void halt_node();

  Status status() const { return status_; }
  const std::string& name() const { return config_.name; }
  const std::string& type() const { return config_.type; }
  const std::string& path() const { return config_.path; }
  const SourceLocation& where() const { return config_.where; }
  NodeCategory category() const { return config_.category; }
  /// Why the node last failed, as set by set_failure_reason() ("" if not given).
  const std::string& failure_reason() const { return failure_reason_; }
  /// How many runs the node has started: a run starts when the node is ticked while not
  /// RUNNING.
  std::uint64_t run_count() const { return run_count_; }
  /// "Type", or "Type 'name'" when the node has a name of its own; used in messages.
  std::string describe() const;

  std::size_t child_count() const { return children_.size(); }
  const Node& child_node(std::size_t index) const;

 protected:
  /// Does the node's work; returns kRunning, kSuccess or kFailure, never kIdle.
  virtual Status tick() = 0;
  /// True during a tick that starts a new run (the node was not RUNNING before it).
  bool starting() const { return starting_; }

  /// Stops work in progress; called by halt_node() only while RUNNING.
  virtual void halt() {}
  /// False for node types whose tick must complete (SyncActionNode, ConditionNode); a
  /// RUNNING result is then reported as an error.
  virtual bool may_return_running() const { return true; }

  /// The value of input (or in-out) port `port` as T: the converted literal, the default, or
  /// the blackboard entry the port names. Throws Error located at the port's value when the
  /// entry has not been written or holds another type.
  template <typename T>
  T get_input(const std::string& port) const {
    std::any scratch;
    const std::any& value = input_value(port, std::type_index(typeid(T)), scratch);
    if constexpr (std::is_same_v<T, std::any>) {
      return value;
    } else {
      return std::any_cast<const T&>(value);
    }
  }

  /// Like get_input() without a copy; valid until the entry is written again.
  template <typename T>
  const T& get_input_ref(const std::string& port) const {
    std::any& scratch = converted_[port];
    return std::any_cast<const T&>(input_value(port, std::type_index(typeid(T)), scratch));
  }

  /// Writes `value` (moved) to the entry output port `port` names; does nothing when the
  /// YAML left the port unconnected. Throws Error when the entry holds another type.
  template <typename T>
  void set_output(const std::string& port, T value) {
    if constexpr (std::is_same_v<T, std::any>) {
      write_output(port, std::move(value));
    } else {
      write_output(port, std::any(std::move(value)));
    }
  }

  /// The component named by component port `port` (declared with component_port<C>).
  template <typename C>
  C& component(const std::string& port) const {
    Component& base = component_base(port, component_kind_of<C>());
    return static_cast<C&>(base);
  }

  /// `text` with every `{key}` replaced by the printed value of that entry ("<unset>" when
  /// the entry has not been written).
  std::string expand(const TextTemplate& text) const;

  /// A random stream determined by the tree's seed, this node's path and run_count(): the
  /// same on every tick of one run, different for each run and each node.
  RandomStream random() const;

  /// The cancellation token for calls this tick makes (plugin calls): it asks to stop once
  /// the deadline of an enclosing Timeout has passed or Tree::request_stop() was called. A
  /// Cancelled exception thrown by tick() makes the node fail with its message as reason.
  StopToken stop_token() const;

  /// Records why the node fails; shown by tracers. Cleared when the node starts again.
  void set_failure_reason(std::string reason) { failure_reason_ = std::move(reason); }

  /// Sends `message` to the tree's log sink.
  void log(const std::string& message) const;

  /// Reports that `done` of `total` steps of `what` are finished to the tree's progress sink
  /// (nothing happens without one). Call it from the thread that ticks the tree.
  void progress(std::size_t done, std::size_t total, const std::string& what) const;

  /// The blackboard of the tree instance this node belongs to.
  Blackboard& blackboard() const { return *config_.blackboard; }

  /// Throws Error(message) located at port `port`'s value (at the node when the port has no
  /// written value or does not exist). Use describe() to name the node in `message`.
  [[noreturn]] void fail(const std::string& port, const std::string& message) const;

  Node& child(std::size_t index = 0) const;
  std::vector<Node*> children() const;
  /// halt_node() on child `index` / on every child from `first` on.
  void halt_child(std::size_t index);
  void halt_children(std::size_t first = 0);

 private:
  friend struct detail::NodeAccess;

  const PortBinding& binding(const std::string& port) const;
  const std::any& input_value(const std::string& port, std::type_index type,
                              std::any& scratch) const;
  const std::any& entry_value(const PortBinding& bound, std::type_index type,
                              std::any& scratch) const;
  void write_output(const std::string& port, std::any value);
  Component& component_base(const std::string& port, ComponentKind kind) const;
  void set_status(Status status);
  // After tick() threw: halts whatever the tick may have left RUNNING, resets to IDLE.
  void abandon(Status previous) noexcept;
  // Rethrows the current exception as an Error located at this node (unless it has a place).
  [[noreturn]] void rethrow_located() const;
  std::string plugin_fault(const std::exception& fault) const;

  NodeConfig config_;
  Status status_ = Status::kIdle;
  std::string failure_reason_;
  std::uint64_t run_count_ = 0;
  bool starting_ = false;
  std::vector<std::unique_ptr<Node>> children_;
  mutable std::map<std::string, std::any> converted_;
};

}  // namespace antipode::bt
