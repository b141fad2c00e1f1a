#pragma once
/// @file
/// MotionPlanner: a collision-free arm motion to a grasp.

#include <string>
#include <vector>

#include "antipode/core/hand.hpp"
#include "antipode/interfaces/component.hpp"

namespace antipode {

/// Joint-space waypoints, each with one position per joint (radians), and their times.
struct Trajectory {
  std::vector<std::string> joint_names;
  std::vector<std::vector<double>> positions_rad;
  std::vector<double> times_s;

  bool empty() const { return positions_rad.empty(); }
};

/// What to plan: from `start_rad` (one value per joint of the planner's arm) to a pose from
/// which `grasp` can be approached.
struct PlanningRequest {
  std::vector<double> start_rad;
  Hand grasp;
  double time_limit_s = 1.0;
};

class MotionPlanner : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kMotionPlanner; }

  /// Returns a trajectory, or an empty one when none was found within the time limit
  /// (`why` then says why). Throws antipode::Error only for malformed requests.
  virtual Trajectory plan(const PlanningRequest& request, std::string* why) const = 0;
};

}  // namespace antipode
