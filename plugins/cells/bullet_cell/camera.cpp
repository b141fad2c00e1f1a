#include "camera.hpp"

#include "antipode/core/error.hpp"

namespace antipode::cells {

Eigen::Isometry3d look_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = target - position;
  if (forward.norm() < 1e-6) throw Error("a camera looks at its own position");
  const Eigen::Vector3d z = forward.normalized();
  Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ());
  if (x.norm() < 1e-6) x = z.cross(Eigen::Vector3d::UnitX());
  x.normalize();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear().col(0) = x;
  pose.linear().col(1) = z.cross(x);
  pose.linear().col(2) = z;
  pose.translation() = position;
  return pose;
}

}  // namespace antipode::cells
