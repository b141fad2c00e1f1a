#include "antipode/io/load_cloud.hpp"
#include "antipode/bt/action_node.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Reads a cloud from a PCD or PLY file (the "camera" of an offline run).
class LoadCloud final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"LoadCloud",
            bt::NodeCategory::kAction,
            {bt::input_port<std::string>("file",
                                         "PCD or PLY file, relative to the working "
                                         "directory"),
             bt::input_port<std::vector<double>>(
                 "view_origin_m", std::vector<double>{},
                 "sensor origin [x, y, z]; empty = the file's VIEWPOINT, else the origin"),
             bt::input_port<std::string>("frame", std::string("sensor"), "the cloud's frame"),
             bt::output_port<CloudPtr>("cloud", "the finite points of the file, one view")},
            0,
            0,
            "Loads a point cloud from a file.",
            {}};
  }

 protected:
  bt::Status tick() override {
    LoadCloudOptions options;
    options.frame = get_input<std::string>("frame");
    const auto origin = get_input<std::vector<double>>("view_origin_m");
    if (origin.size() == 3) {
      options.view_origin_m = Eigen::Vector3d(origin[0], origin[1], origin[2]).cast<float>();
    } else if (!origin.empty()) {
      fail("view_origin_m",
           "view_origin_m must have 3 numbers, got " + std::to_string(origin.size()));
    }
    auto cloud = std::make_shared<Cloud>(load_cloud(get_input<std::string>("file"), options));
    log(std::to_string(cloud->size()) + " points loaded");
    set_output("cloud", CloudPtr(std::move(cloud)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_load_cloud(bt::NodeRegistry& registry) { registry.register_node<LoadCloud>(); }

}  // namespace antipode::pipeline
