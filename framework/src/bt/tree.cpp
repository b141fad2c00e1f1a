#include "antipode/bt/tree.hpp"

#include <algorithm>
#include <thread>

#include "tree_context.hpp"

namespace antipode::bt {
namespace {

void visit_node(const Node& node, int depth, const std::function<void(const Node&, int)>& visitor) {
  visitor(node, depth);
  for (std::size_t i = 0; i < node.child_count(); ++i) {
    visit_node(node.child_node(i), depth + 1, visitor);
  }
}

}  // namespace

Tree::Tree(std::unique_ptr<Node> root, std::shared_ptr<Blackboard> blackboard,
           std::shared_ptr<detail::TreeContext> context, std::string main_tree)
    : context_(std::move(context)),
      blackboard_(std::move(blackboard)),
      root_(std::move(root)),
      main_tree_(std::move(main_tree)) {}

Tree::Tree(Tree&&) noexcept = default;

Tree& Tree::operator=(Tree&& other) noexcept {
  if (this != &other) {
    Tree old(std::move(*this));
    context_ = std::move(other.context_);
    blackboard_ = std::move(other.blackboard_);
    root_ = std::move(other.root_);
    main_tree_ = std::move(other.main_tree_);
  }
  return *this;
}

Tree::~Tree() {
  if (!root_) return;
  context_->observers.clear();
  try {
    root_->halt_node();
  } catch (...) {
    // A node failing to halt must not escalate while the tree is being destroyed.
  }
  root_.reset();
}

Status Tree::tick_once() {
  Status status = Status::kIdle;
  try {
    status = root_->execute_tick();
  } catch (...) {
    try {
      root_->halt_node();
    } catch (...) {
      // Keep the first error.
    }
    throw;
  }
  if (is_completed(status)) root_->halt_node();
  return status;
}

Status Tree::tick_while_running(std::chrono::milliseconds sleep) {
  Status status = tick_once();
  while (status == Status::kRunning) {
    if (sleep.count() > 0) std::this_thread::sleep_for(sleep);
    status = tick_once();
  }
  return status;
}

void Tree::halt() { root_->halt_node(); }

void Tree::request_stop() { context_->stop_source.request_stop(); }

void Tree::add_observer(TreeObserver* observer) {
  if (observer != nullptr) context_->observers.push_back(observer);
}

void Tree::add_observer(std::shared_ptr<TreeObserver> observer) {
  if (!observer) return;
  context_->observers.push_back(observer.get());
  context_->owned_observers.push_back(std::move(observer));
}

void Tree::remove_observer(TreeObserver* observer) {
  auto& observers = context_->observers;
  observers.erase(std::remove(observers.begin(), observers.end(), observer), observers.end());
  auto& owned = context_->owned_observers;
  owned.erase(std::remove_if(owned.begin(), owned.end(),
                             [&](const auto& held) { return held.get() == observer; }),
              owned.end());
}

void Tree::set_log_sink(LogSink sink) { context_->log_sink = std::move(sink); }

void Tree::set_progress_sink(ProgressSink sink) { context_->progress_sink = std::move(sink); }

void Tree::visit(const std::function<void(const Node&, int)>& visitor) const {
  visit_node(*root_, 0, visitor);
}

std::shared_ptr<Component> Tree::component(const std::string& name) const {
  const auto found = context_->components.find(name);
  return found == context_->components.end() ? nullptr : found->second;
}

std::vector<std::string> Tree::component_names() const {
  std::vector<std::string> names;
  for (const auto& [name, component] : context_->components) names.push_back(name);
  return names;
}

std::uint64_t Tree::seed() const { return context_->seed; }

}  // namespace antipode::bt
