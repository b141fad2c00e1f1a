#include "antipode/bt/action_node.hpp"
#include "antipode/io/save_cloud.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// Writes a cloud to a binary PCD file (save_cloud_pcd: x, y, z and the view that saw each
/// point), all or nothing. An empty `file` writes nothing.
class WriteCloud final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"WriteCloud",
            bt::NodeCategory::kAction,
            {bt::input_port<CloudPtr>("cloud", "the cloud to write"),
             bt::input_port<std::string>("file", std::string(), "output PCD file; empty = none")},
            0,
            0,
            "Writes a cloud to a PCD file.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const CloudPtr cloud = get_input<CloudPtr>("cloud");
    save_cloud_pcd(*cloud, file);
    log(std::to_string(cloud->size()) + " points written to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_write_cloud(bt::NodeRegistry& registry) { registry.register_node<WriteCloud>(); }

}  // namespace antipode::pipeline
