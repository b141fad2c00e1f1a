#pragma once
// The simulated parallel gripper: a free-floating palm pulled towards the commanded hand pose
// by a force- and torque-bounded drive (like a robot's wrist that stalls against an obstacle),
// and two fingers on prismatic joints whose motors are force-limited.

#include <set>

#include "antipode/core/hand_geometry.hpp"
#include "physics_world.hpp"

class btSliderConstraint;

namespace antipode::cells {

struct GripperOptions {
  HandGeometry geometry;           ///< finger sizes and apertures (the Baxter defaults)
  double palm_thickness_m = 0.02;  ///< palm box behind the palm face
  double finger_mass_kg = 0.1;
  double palm_mass_kg = 10.0;    ///< heavy like a wrist on an arm: it keeps the grip stiff
  double hand_force_n = 300.0;   ///< bound of the drive carrying the hand (VGN/GIGA: 300 N)
  double hand_torque_nm = 30.0;  ///< bound of the drive's torque
  double finger_force_n = 10.0;  ///< per finger; docs/cell.md says why not 20 N
  double finger_speed_m_s = 0.1;
  double friction = 1.0;
};

/// Adds itself to a world at a hand pose (fingers fully open) and removes itself when
/// destroyed. Hand frame as in hand_geometry.hpp: x approach, y closing, origin at the
/// centre of the palm face.
class Gripper {
 public:
  Gripper(PhysicsWorld& world, const GripperOptions& options, const Eigen::Isometry3d& X_BaseHand);
  ~Gripper();
  Gripper(const Gripper&) = delete;
  Gripper& operator=(const Gripper&) = delete;

  /// Commands the hand to `X_BaseHand`; the drive pulls it there from the next step on.
  void move_to(const Eigen::Isometry3d& X_BaseHand);
  /// The commanded hand pose.
  const Eigen::Isometry3d& pose() const { return X_BaseHand_; }
  /// Where the hand is (it lags the command when it pushes against something).
  Eigen::Isometry3d actual_pose() const;
  /// Drives both fingers: negative closes, positive opens (m/s), force-limited.
  void drive_fingers(double velocity_m_s);
  /// Inner distance between the fingers now.
  double aperture_m() const;

  /// Non-gripper bodies touching any part of the gripper now.
  std::set<int> touching(double tolerance_m = 0.0) const;
  /// Objects touching both fingers now.
  std::set<int> pinched(double tolerance_m) const;

 private:
  /// One step of the palm's drive: the impulse that would reach the command in one step,
  /// clipped to the force and torque bounds.
  void drive();

  PhysicsWorld& world_;
  GripperOptions options_;
  Eigen::Isometry3d X_BaseHand_;
  int palm_ = -1;
  int fingers_[2] = {-1, -1};  // at -y, at +y
  btSliderConstraint* sliders_[2] = {nullptr, nullptr};
};

}  // namespace antipode::cells
