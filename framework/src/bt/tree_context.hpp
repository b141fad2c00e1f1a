#pragma once
// What all nodes of one loaded tree share: the seed, the components, the observers and the
// log sink. Internal to the engine.

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "antipode/bt/node.hpp"
#include "antipode/bt/observer.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode::bt::detail {

struct TreeContext {
  std::uint64_t seed = 0;
  std::map<std::string, std::shared_ptr<Component>> components;
  /// The plugin type of each component, by name ("classifier" -> "hog_svm_classifier").
  std::map<std::string, std::string> component_plugins;
  std::vector<TreeObserver*> observers;
  std::vector<std::shared_ptr<TreeObserver>> owned_observers;
  LogSink log_sink;
  ProgressSink progress_sink;
  /// Stops every call made with `stop` (Tree::request_stop()).
  StopSource stop_source;
  /// The token nodes pass to their calls now: the source's, with the deadline of every
  /// Timeout being ticked (each sets it around its child's tick).
  StopToken stop = stop_source.token();
  /// The plugin libraries whose code the tree's nodes run; released after the nodes and
  /// blackboards (every node holds this context, and the Tree drops it last).
  std::vector<std::shared_ptr<const void>> libraries;

  void notify(const Node& node, Status previous, Status current) const {
    if (observers.empty()) return;
    const auto now = std::chrono::steady_clock::now();
    for (TreeObserver* observer : observers) {
      observer->on_status_change(node, previous, current, now);
    }
  }
};

// The loader's access to a node's children.
struct NodeAccess {
  static void add_child(Node& parent, std::unique_ptr<Node> child) {
    parent.children_.push_back(std::move(child));
  }
  static TreeContext* context(const Node& node) { return node.config_.context.get(); }
  static const PortBinding& binding(const Node& node, const std::string& port) {
    return node.binding(port);
  }
};

}  // namespace antipode::bt::detail
