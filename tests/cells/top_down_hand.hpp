#pragma once
// Test helper for the cell's grasp tests.

#include "antipode/core/hand.hpp"

namespace antipode::cells::testing {

/// A hand approaching straight down, closing along base x, palm face at (x, y, z).
inline Hand top_down(double x, double y, double z) {
  Hand hand;
  Eigen::Matrix3d r;
  r.col(0) = -Eigen::Vector3d::UnitZ();
  r.col(1) = Eigen::Vector3d::UnitX();
  r.col(2) = r.col(0).cross(r.col(1));
  hand.X_FrameHand.linear() = r;
  hand.X_FrameHand.translation() << x, y, z;
  return hand;
}

}  // namespace antipode::cells::testing
