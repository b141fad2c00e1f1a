#include "antipode/io/load_cloud.hpp"

#include <cmath>
#include <optional>

#include "antipode/bt/action_node.hpp"
#include "nodes.hpp"

namespace antipode::pipeline {
namespace {

/// [x, y, z, qw, qx, qy, qz] as a pose, or nothing unless the numbers are finite and the
/// quaternion a unit one (within 1e-3).
std::optional<Eigen::Isometry3d> pose_of(const std::vector<double>& v) {
  const Eigen::Quaterniond q(v[3], v[4], v[5], v[6]);
  if (!Eigen::Vector3d(v[0], v[1], v[2]).allFinite() || !q.coeffs().allFinite() ||
      std::abs(q.norm() - 1.0) > 1e-3)
    return std::nullopt;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = q.normalized().toRotationMatrix();
  X.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  return X;
}

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
             bt::input_port<std::vector<double>>(
                 "camera_pose", std::vector<double>{},
                 "the pose of the file's frame (a depth camera's: the camera's) in `frame`, "
                 "[x, y, z, qw, qx, qy, qz] (m, a unit quaternion): the cloud is moved into "
                 "`frame`; empty = the cloud stays in the file's frame"),
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
    const auto numbers = get_input<std::vector<double>>("camera_pose");
    std::optional<Eigen::Isometry3d> pose;
    if (!numbers.empty()) {
      if (numbers.size() == 7) pose = pose_of(numbers);
      if (!pose)
        fail("camera_pose",
             "camera_pose must be 7 finite numbers [x, y, z, qw, qx, qy, qz] with a unit "
             "quaternion, got " +
                 std::to_string(numbers.size()) + " numbers");
    }
    const std::string file = get_input<std::string>("file");
    std::string note;
    auto cloud = std::make_shared<Cloud>(pose ? load_cloud_into(file, *pose, options, &note)
                                              : load_cloud(file, options));
    if (!note.empty()) log("note: " + note);
    log(std::to_string(cloud->size()) + " points loaded" +
        (pose ? " into frame '" + options.frame + "'" : ""));
    set_output("cloud", CloudPtr(std::move(cloud)));
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_load_cloud(bt::NodeRegistry& registry) { registry.register_node<LoadCloud>(); }

}  // namespace antipode::pipeline
