#pragma once
// The cell of the arm benchmarks: Baxter's right arm with the table top at z = -0.295 and a
// 0.3 x 0.3 m box with 0.15 m walls centred at (0.75, -0.2) in the base frame.

#include <Eigen/Geometry>

#include "arm_collision_world.hpp"

namespace antipode::bench {

inline Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

constexpr double kBoxX = 0.75, kBoxY = -0.2, kTableZ = -0.295;

inline void add_table_and_box(collision::ArmCollisionWorld& world) {
  world.add_box("table", at(0.8, -0.2, kTableZ - 0.025), Eigen::Vector3d(0.8, 1.2, 0.05));
  const double h = 0.15, t = 0.01, z = kTableZ + h / 2;
  world.add_box("wall_x0", at(kBoxX - 0.15, kBoxY, z), Eigen::Vector3d(t, 0.3, h));
  world.add_box("wall_x1", at(kBoxX + 0.15, kBoxY, z), Eigen::Vector3d(t, 0.3, h));
  world.add_box("wall_y0", at(kBoxX, kBoxY - 0.15, z), Eigen::Vector3d(0.3, t, h));
  world.add_box("wall_y1", at(kBoxX, kBoxY + 0.15, z), Eigen::Vector3d(0.3, t, h));
}

}  // namespace antipode::bench
