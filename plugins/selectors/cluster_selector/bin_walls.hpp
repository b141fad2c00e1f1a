#pragma once
// A bin the objects lie in, known from the cell's layout (a clutter box): its walls are a
// fixture, never an object to grasp. A hand whose fingers straddle a wall closes on the wall
// (seen from the cloud, the wall's points between the fingers look like an object's), so the
// selector drops every hand whose body or closing region reaches into a wall.

#include <vector>

#include <Eigen/Core>

#include "antipode/core/hand.hpp"
#include "antipode/geometry/hand_body.hpp"

namespace antipode::selectors {

/// An axis-aligned rectangular bin in the hands' frame (metres): inner size, walls standing
/// on `floor_z_m` `wall_height_m` high and `wall_thickness_m` thick outside the inner size.
struct Bin {
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d inner_size_m = Eigen::Vector2d::Zero();
  double floor_z_m = 0.0;
  double wall_height_m = 0.06;
  double wall_thickness_m = 0.01;
};

/// The bin's four walls, each filled with points on a grid no coarser than `step_m`.
std::vector<Eigen::Vector3d> wall_points(const Bin& bin, double step_m = 0.005);

/// True when a point of `walls` lies in the box that bounds the hand's fingers, palm and the
/// closing region between the fingers (hand_body.hpp) at the hand's pose.
bool reaches_into_wall(const Hand& hand, const HandBody& body,
                       const std::vector<Eigen::Vector3d>& walls);

}  // namespace antipode::selectors
