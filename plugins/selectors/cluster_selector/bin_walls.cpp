#include "bin_walls.hpp"

#include <fcl/narrowphase/collision.h>

namespace antipode::selectors {
namespace {

fcl::Boxd box_of(const Eigen::Vector3d& size_m) { return {size_m.x(), size_m.y(), size_m.z()}; }

fcl::Transform3d at(const Eigen::Vector3d& center_m) {
  fcl::Transform3d pose = fcl::Transform3d::Identity();
  pose.translation() = center_m;
  return pose;
}

}  // namespace

BinWalls::BinWalls(const Bin& bin, const HandBody& body) {
  const Eigen::Vector3d lo = body.palm.min_m.cwiseMin(body.finger_minus_y.min_m);
  const Eigen::Vector3d hi = body.palm.max_m.cwiseMax(body.finger_plus_y.max_m);
  hand_box_ = box_of(hi - lo);
  hand_box_center_ = (lo + hi) / 2;
  for (const Eigen::AlignedBox3d& wall : bin.walls())
    walls_.emplace_back(box_of(wall.sizes()), at(wall.center()));
}

bool BinWalls::reached_by(const Hand& hand) const {
  fcl::Transform3d pose = hand.X_FrameHand;
  pose.translation() = hand.X_FrameHand * hand_box_center_;
  const fcl::CollisionRequestd request;
  for (const auto& [wall, wall_pose] : walls_) {
    fcl::CollisionResultd result;
    if (fcl::collide(&hand_box_, pose, &wall, wall_pose, request, result) > 0) return true;
  }
  return false;
}

}  // namespace antipode::selectors
