#pragma once
// A bin the objects lie in (antipode/geometry/bin.hpp): its walls are a fixture, never an
// object to grasp. A hand whose fingers straddle a wall closes on the wall
// (seen from the cloud, the wall's points between the fingers look like an object's), so the
// selector drops every hand whose body or closing region reaches into a wall.

#include <utility>
#include <vector>

#include <fcl/geometry/shape/box.h>

#include <Eigen/Core>

#include "antipode/core/hand.hpp"
#include "antipode/geometry/bin.hpp"
#include "antipode/geometry/hand_body.hpp"

namespace antipode::selectors {

/// Tells whether a hand reaches into the bin's walls: the box that bounds its fingers, palm
/// and the closing region between the fingers (hand_body.hpp), at the hand's pose, overlaps
/// (or touches) a wall - FCL's exact box-box test. Made once per hand geometry; a check
/// allocates nothing unless the boxes overlap.
class BinWalls {
 public:
  BinWalls(const Bin& bin, const HandBody& body);

  bool reached_by(const Hand& hand) const;

 private:
  fcl::Boxd hand_box_;
  Eigen::Vector3d hand_box_center_;  ///< in the hand frame
  std::vector<std::pair<fcl::Boxd, fcl::Transform3d>> walls_;
};

}  // namespace antipode::selectors
