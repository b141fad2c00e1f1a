#include <cstdio>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/cloud.hpp"
#include "antipode/geometry/depth_scale.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Corrects each view's depth scale against a support of known height (a table whose height
/// the cell knows): the view's points are scaled about its origin until the support plane
/// they show lies at `support_height_m` (antipode/geometry/depth_scale.hpp). Logs each view's
/// factor; a view without a recognisable support is passed on unchanged.
class CorrectDepthScale final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"CorrectDepthScale",
            bt::NodeCategory::kAction,
            {bt::input_port<CloudPtr>("cloud", "a capture with view origins (CaptureCloud)"),
             bt::input_port<double>("support_height_m",
                                    "the support's height: z of the horizontal plane the "
                                    "objects stand on, in the cloud's frame"),
             bt::input_port<double>("max_correction", 0.1,
                                    "views needing a factor beyond 1 +- this are left as they are"),
             bt::output_port<CloudPtr>("corrected", "the cloud with each view rescaled")},
            0,
            0,
            "Corrects each view's depth scale so that the support lies at its known height.",
            {}};
  }

 protected:
  bt::Status tick() override {
    auto cloud = std::make_shared<Cloud>(*get_input<CloudPtr>("cloud"));
    DepthScaleOptions options;
    options.support_height_m = get_input<double>("support_height_m");
    options.max_correction = get_input<double>("max_correction");
    if (!(options.max_correction > 0.0 && options.max_correction < 1.0))
      fail("max_correction", "port 'max_correction' of " + describe() + " must be in (0, 1)");
    const std::vector<ViewScale> views = correct_depth_scale(*cloud, options, random());
    for (std::size_t v = 0; v < views.size(); ++v) {
      char line[160];
      if (views[v].corrected)
        std::snprintf(line, sizeof line, "view %zu: depths x%.4f (the support seen at z %.4f m)", v,
                      views[v].factor, views[v].seen_height_m);
      else
        std::snprintf(line, sizeof line, "view %zu: left as it is (no support plane to go by)", v);
      log(line);
    }
    set_output("corrected", CloudPtr(std::move(cloud)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_correct_depth_scale(bt::NodeRegistry& registry) {
  registry.register_node<CorrectDepthScale>();
}

}  // namespace antipode::pipeline
