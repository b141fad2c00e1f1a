#include <utility>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/error.hpp"
#include "antipode/core/view_selection.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Keeps the points of some views of a multi-view cloud: a single-view cloud from a
/// registered pair, for example (the paper's 1V against 2V).
class SelectViews final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"SelectViews",
            bt::NodeCategory::kAction,
            {bt::input_port<CloudPtr>("cloud", "a cloud with view origins and view masks"),
             bt::input_port<std::vector<int>>("views", "indices of the views to keep"),
             bt::output_port<CloudPtr>("selected", "their points; view k = views[k]")},
            0,
            0,
            "Keeps the points some views of a cloud saw.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const CloudPtr cloud = get_input<CloudPtr>("cloud");
    const auto views = get_input<std::vector<int>>("views");
    Cloud points;
    try {
      points = points_of_views(*cloud, views);
    } catch (const Error& e) {
      fail("views", e.message());
    }
    auto selected = std::make_shared<Cloud>(std::move(points));
    log(std::to_string(selected->size()) + " of " + std::to_string(cloud->size()) + " points");
    set_output("selected", CloudPtr(std::move(selected)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_select_views(bt::NodeRegistry& registry) { registry.register_node<SelectViews>(); }

}  // namespace antipode::pipeline
