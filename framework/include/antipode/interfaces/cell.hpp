#pragma once
/// @file
/// Cell: the robot's world, real or simulated - it captures views and executes grasps.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"

namespace antipode {

/// What a cell with ground truth (a simulated one) knows of an object in its workspace.
struct ObjectTruth {
  std::string name;  ///< its name in the scene ("004_sugar_box", "cylinder 3", ...)
  Eigen::Isometry3d X_BaseObject = Eigen::Isometry3d::Identity();  ///< its pose now
  /// Its narrowest horizontal extent as it lies now (narrowest_extent.hpp, with +z of the
  /// base frame up): a gripper closing horizontally holds it from above only when this lies
  /// within its aperture. Metres.
  double narrowest_horizontal_m = 0.0;
};

/// A cell's world as save() found it: opaque to all but the cell that saved it.
class CellState {
 public:
  virtual ~CellState() = default;
};

/// One caller at a time: a cell is the state of one robot and its world, and none of its
/// functions may run concurrently with another on the same cell (a tree ticks in one
/// thread). Poses are in the cell's base frame, lengths in metres. Errors: antipode::Error
/// for a request that names what the cell lacks (an unknown view); an attempt that goes
/// wrong is an outcome of execute(), never an exception.
class Cell : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kCell; }

  /// Names of the views this cell can capture (e.g. "left", "right").
  virtual std::vector<std::string> view_names() const = 0;

  /// A cloud in the cell's base frame combining the named views; view v of the result is
  /// `views[v]`. Throws antipode::Error for an unknown view name.
  virtual Cloud capture(const std::vector<std::string>& views) = 0;

  /// The arm's joint state now; empty for a cell without an arm (a free-floating hand).
  virtual JointState arm_state() const = 0;

  /// Executes `request.grasp` with a gripper of `request.gripper` (following the request's
  /// trajectory when it is not empty) and reports the attempt. A request the cell cannot
  /// execute (another frame than "base", a pose that is not a rigid motion, a gripper it
  /// cannot be) gives outcome kNotExecuted with the reason; it never throws for a bad
  /// request. With a trajectory, the arm follows it first; an arm link touching the
  /// environment on the way ends the attempt with kArmCollision, naming link and object.
  virtual GraspAttempt execute(const GraspRequest& request) = 0;

  /// How many objects are left in the cell's workspace (picked objects leave it, and so do
  /// objects knocked off the table or, in a cell with a box, out of the box); nullopt when
  /// the cell cannot tell (a real cell without ground truth). A clear-the-box loop ends when
  /// it reaches 0.
  virtual std::optional<int> objects_left() const { return std::nullopt; }

  /// The objects left in the workspace (as objects_left() counts them), as the cell's ground
  /// truth has them, for benches and tests that explain what was left and why; empty when the
  /// cell has none (a real cell).
  virtual std::vector<ObjectTruth> object_truth() const { return {}; }

  /// How many objects the last reset() put into the scene, counting those that came to rest
  /// outside the workspace while it was filled (bounced out of the box); nullopt when the
  /// cell cannot tell (a real cell). With objects_left() at the start of a run, it tells how
  /// many were missed while filling.
  virtual std::optional<int> objects_placed() const { return std::nullopt; }

  /// Restores the cell's initial state for `seed`.
  virtual void reset(std::uint64_t seed) = 0;

  /// The world as it is now (every object's pose and motion, the clock), for restore(); null
  /// when the cell cannot save it (a real cell, whose default this is). Trials started from
  /// one saved state are independent: each sees the same world, whatever the ones before did.
  virtual std::shared_ptr<const CellState> save() const { return nullptr; }

  /// Puts the world back as save() found it. Throws antipode::Error for a state that this
  /// cell did not save (another cell's, or a cell that cannot restore).
  virtual void restore(const CellState& state);
};

}  // namespace antipode
