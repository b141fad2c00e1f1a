#pragma once
// Conversions between Eigen (double) and Bullet (float build) poses.

#include <btBulletDynamicsCommon.h>

#include <Eigen/Geometry>

namespace antipode::cells {

inline btVector3 to_bullet(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
inline Eigen::Vector3d from_bullet(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline btTransform to_bullet(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), to_bullet(pose.translation()));
}

inline Eigen::Isometry3d from_bullet(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).normalized().toRotationMatrix();
  pose.translation() = from_bullet(t.getOrigin());
  return pose;
}

}  // namespace antipode::cells
