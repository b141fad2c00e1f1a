#pragma once
/// @file
/// Cell: the robot's world, real or simulated - it captures views and executes grasps.

#include <cstdint>
#include <string>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/motion_planner.hpp"

namespace antipode {

/// How a grasp attempt ended, judged by the cell (ground truth in simulation).
enum class GraspOutcome : std::uint8_t {
  kSuccess,
  kCollisionOnApproach,
  kEmptyGrasp,
  kSlipped,
  kObjectKnockedOut,
  kNotExecuted,
};

const char* to_string(GraspOutcome outcome);

class Cell : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kCell; }

  /// Names of the views this cell can capture (e.g. "left", "right").
  virtual std::vector<std::string> view_names() const = 0;

  /// A cloud in the cell's base frame combining the named views; view v of the result is
  /// `views[v]`. Throws antipode::Error for an unknown view name.
  virtual Cloud capture(const std::vector<std::string>& views) = 0;

  /// Executes `grasp` (following `trajectory` when it is not empty) and reports the outcome.
  virtual GraspOutcome execute(const Hand& grasp, const Trajectory& trajectory) = 0;

  /// Restores the cell's initial state for `seed`.
  virtual void reset(std::uint64_t seed) = 0;
};

}  // namespace antipode
