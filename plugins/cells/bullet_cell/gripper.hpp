#pragma once
// The simulated parallel gripper, as an articulated body in Featherstone's reduced
// coordinates (Bullet's btMultiBody): a palm and two fingers on prismatic joints that a gear
// keeps symmetric, as a parallel gripper's rack does. A fixed constraint with a bounded force
// pulls the palm to the commanded hand pose (a robot's wrist that stalls against an
// obstacle), and each finger's velocity motor squeezes with a bounded force.
//
// Reduced coordinates keep the finger joints exact however hard they press: the earlier
// rigid bodies on slider constraints let the fingers and a held object slide together along
// the closing direction and sink into curved hulls until the object popped out.

#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "antipode/core/hand_geometry.hpp"
#include "physics_world.hpp"

namespace antipode::cells {

struct GripperOptions {
  HandGeometry geometry;  ///< finger sizes, apertures and palm thickness
  double finger_mass_kg = 0.1;
  double palm_mass_kg = 1.0;
  double hand_force_n = 300.0;   ///< bound of the drive carrying the hand (VGN/GIGA: 300 N)
  double finger_force_n = 20.0;  ///< squeeze of each finger (VGN/GIGA: 20 N)
  double finger_speed_m_s = 0.1;
  double friction = 1.0;
  /// The fingers' and palm's spinning friction (m): Bullet resists a twist about a contact's
  /// normal up to (this x the object's friction + the object's spinning friction x `friction`)
  /// x the contact's normal force. 0: rigid fingers, whose contacts with a curved object are
  /// points that resist no twist; a soft pad's contact patch of radius a resists about
  /// 2/3 a x its friction.
  double torsional_friction_m = 0.0;
};

/// Adds itself to a world at a hand pose (fingers fully open) and removes itself when
/// destroyed. Hand frame as in hand_geometry.hpp: x approach, y closing, origin at the
/// centre of the palm face. Gravity does not act on it (it is carried by the arm).
class Gripper {
 public:
  Gripper(PhysicsWorld& world, const GripperOptions& options, const Eigen::Isometry3d& X_BaseHand);
  ~Gripper();
  struct Parts;
  Gripper(const Gripper&) = delete;
  Gripper& operator=(const Gripper&) = delete;

  /// Commands the hand to `X_BaseHand`; the drive pulls it there from the next step on.
  void move_to(const Eigen::Isometry3d& X_BaseHand);
  /// The commanded hand pose.
  const Eigen::Isometry3d& pose() const { return X_BaseHand_; }
  /// Where the hand is (it lags the command when it pushes against something).
  Eigen::Isometry3d actual_pose() const;
  /// Drives the fingers: negative closes, positive opens (m/s), force-limited.
  void drive_fingers(double velocity_m_s);
  /// How far finger `side` (0: -y, 1: +y) has moved in from fully open.
  double finger_travel_m(int side) const;
  /// Inner distance between the fingers now.
  double aperture_m() const;

  /// Non-gripper bodies touching any part of the gripper now.
  std::set<int> touching(double tolerance_m = 0.0) const;
  /// The same, with the part that touches each: ("palm" | "finger -y" | "finger +y", id).
  std::vector<std::pair<std::string, int>> touching_parts(double tolerance_m = 0.0) const;
  /// Objects touching both fingers now.
  std::set<int> pinched(double tolerance_m) const;

 private:
  /// Before every physics step: the drive's target and the gravity compensation.
  void drive();

  PhysicsWorld& world_;
  GripperOptions options_;
  Eigen::Isometry3d X_BaseHand_;
  std::unique_ptr<Parts> parts_;
  int palm_ = -1;
  int fingers_[2] = {-1, -1};  // at -y, at +y
};

}  // namespace antipode::cells
