#include <algorithm>

#include "antipode/bt/action_node.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

// The points of `cloud` seen by any of `views`, renumbered as views 0, 1, ... in that order.
Cloud points_of_views(const Cloud& cloud, const std::vector<int>& views) {
  Cloud out;
  out.frame = cloud.frame;
  for (const int v : views) {
    if (static_cast<std::size_t>(v) < cloud.view_origins_m.size()) {
      out.view_origins_m.push_back(cloud.view_origins_m[static_cast<std::size_t>(v)]);
    }
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::uint32_t mask = cloud.view_masks.empty() ? 1u : cloud.view_masks[i];
    std::uint32_t kept = 0;
    for (std::size_t k = 0; k < views.size(); ++k) {
      if ((mask >> static_cast<unsigned>(views[k]) & 1u) != 0) kept |= 1u << k;
    }
    if (kept == 0) continue;
    out.points_m.push_back(cloud.points_m[i]);
    if (!cloud.normals.empty()) out.normals.push_back(cloud.normals[i]);
    out.view_masks.push_back(kept);
  }
  return out;
}

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
    if (views.empty()) fail("views", "views must name at least one view");
    // A cloud without view origins is one view (view 0), as everywhere else.
    const std::size_t count = std::max<std::size_t>(1, cloud->view_origins_m.size());
    for (const int v : views) {
      if (v < 0 || v >= 32 || static_cast<std::size_t>(v) >= count) {
        fail("views", "view " + std::to_string(v) + " is not in the cloud, which has " +
                          std::to_string(count) + " view(s)");
      }
    }
    auto selected = std::make_shared<Cloud>(points_of_views(*cloud, views));
    log(std::to_string(selected->size()) + " of " + std::to_string(cloud->size()) + " points");
    set_output("selected", CloudPtr(std::move(selected)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_select_views(bt::NodeRegistry& registry) { registry.register_node<SelectViews>(); }

}  // namespace antipode::pipeline
