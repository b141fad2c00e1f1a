#include "grasp_attempt.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "antipode/geometry/hand_body.hpp"
#include "surface_samples.hpp"

namespace antipode::cells {
namespace {

Eigen::Isometry3d shifted(const Eigen::Isometry3d& pose, const Eigen::Vector3d& by) {
  Eigen::Isometry3d out = pose;
  out.translation() += by;
  return out;
}

double distance_m(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

std::string millimetres(double metres) {
  std::ostringstream out;
  out.precision(0);
  out << std::fixed << metres * 1000.0 << " mm";
  return out.str();
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::vector<std::string> part_names(const PhysicsWorld& world,
                                    const std::vector<std::pair<std::string, int>>& parts) {
  std::vector<std::string> out;
  for (const auto& [part, id] : parts) out.push_back(part + ": " + world.name(id));
  return out;
}

// What overlaps `box` (in hand coordinates) of a hand at `X_BaseHand`: "prefix: name" for
// every body of the scene, or only objects when `objects_only`.
std::vector<std::string> overlaps(const PhysicsWorld& world, const HandBox& box,
                                  const Eigen::Isometry3d& X_BaseHand, const std::string& prefix,
                                  bool objects_only) {
  const Eigen::Vector3d centre = (box.min_m + box.max_m) / 2;
  const Eigen::Vector3d half = (box.max_m - box.min_m) / 2;
  std::vector<std::string> names;
  for (int id : world.overlapping(X_BaseHand * Eigen::Translation3d(centre), half))
    if (world.has(id) && world.role(id) != BodyRole::kGripper &&
        (!objects_only || world.role(id) == BodyRole::kObject))
      names.push_back(prefix.empty() ? world.name(id) : prefix + ": " + world.name(id));
  return names;
}

// The objects in the closing region of a hand at `X_BaseHand`.
std::vector<std::string> objects_between_fingers(const PhysicsWorld& world, const HandBody& body,
                                                 const Eigen::Isometry3d& X_BaseHand) {
  const HandBox region{{0.0, -body.half_aperture_m, -body.half_height_m},
                       {body.depth_m, body.half_aperture_m, body.half_height_m}};
  return overlaps(world, region, X_BaseHand, "", true);
}

// Everything the fingers and the palm of a hand at `X_BaseHand` overlap.
std::vector<std::string> gripper_overlaps(const PhysicsWorld& world, const HandBody& body,
                                          const Eigen::Isometry3d& X_BaseHand) {
  std::vector<std::string> names;
  for (const auto& [box, part] :
       {std::pair{body.palm, "palm"}, std::pair{body.finger_minus_y, "finger -y"},
        std::pair{body.finger_plus_y, "finger +y"}}) {
    const auto found = overlaps(world, box, X_BaseHand, part, false);
    names.insert(names.end(), found.begin(), found.end());
  }
  return names;
}

// The true surfaces around the hand (GraspAttempt::surface_at_closing_m): a 16 cm cube
// centred in the closing region.
std::vector<Eigen::Vector3f> surface_near_hand(const PhysicsWorld& world,
                                               const HandGeometry& geometry,
                                               const Eigen::Isometry3d& X_BaseHand) {
  Eigen::Isometry3d X_BaseRegion = X_BaseHand;
  X_BaseRegion.translation() += X_BaseHand.linear().col(0) * (geometry.depth_m / 2);
  return surface_points_near(world, X_BaseRegion, Eigen::Vector3d::Constant(0.08), 0.0025, 60000);
}

// Drives the hand from the stand-off pose to the grasp pose, one approach step per physics
// step, then gives it up to `arrive_s` to settle there. Records the first contact on the way.
void approach(PhysicsWorld& world, Gripper& gripper, const Eigen::Isometry3d& X_BaseHand,
              const AttemptOptions& options, GraspAttempt& record) {
  const Eigen::Vector3d direction = X_BaseHand.linear().col(0);
  const int steps = int(std::ceil(options.standoff_m / options.approach_step_m));
  const int arrive_steps = int(std::ceil(options.arrive_s / world.options().time_step_s));
  for (int i = 1; i <= steps + arrive_steps; ++i) {
    const double back = options.standoff_m * std::max(0.0, 1.0 - double(i) / steps);
    gripper.move_to(shifted(X_BaseHand, -back * direction));
    world.step();
    if (record.first_contact.empty()) {
      const auto parts = gripper.touching_parts();
      if (!parts.empty()) {
        record.first_contact = part_names(world, parts).front();
        record.first_contact_before_pose_m = distance_m(gripper.actual_pose(), X_BaseHand);
      }
    }
    if (i >= steps && distance_m(gripper.actual_pose(), X_BaseHand) <= options.arrived_m) break;
  }
}

struct Rise {
  double highest_m = 0.0;
  double final_m = 0.0;
};

// Lifts and holds; returns how far each of `objects` rose on the way and in the end.
std::map<int, Rise> lift_and_hold(PhysicsWorld& world, Gripper& gripper,
                                  const AttemptOptions& options, const std::set<int>& objects) {
  std::map<int, double> start_z;
  std::map<int, Rise> rise;
  for (int id : objects) start_z[id] = world.pose(id).translation().z();
  const auto track = [&] {
    for (int id : objects) {
      Rise& r = rise[id];
      r.final_m = world.pose(id).translation().z() - start_z[id];
      r.highest_m = std::max(r.highest_m, r.final_m);
    }
  };
  const double dt = world.options().time_step_s;
  const int steps = std::max(1, int(std::ceil(options.lift_m / (options.lift_speed_m_s * dt))));
  const Eigen::Isometry3d start = gripper.pose();
  for (int i = 1; i <= steps; ++i) {
    const double s = double(i) / steps, eased = s * s * (3.0 - 2.0 * s);  // no jerk at the ends
    gripper.move_to(shifted(start, Eigen::Vector3d(0, 0, options.lift_m * eased)));
    world.step();
    track();
  }
  for (int i = int(std::ceil(options.hold_s / dt)); i > 0; --i) {
    world.step();
    track();
  }
  return rise;
}

// Held up by the gripper alone: touching no fixture (an object that swung about the
// fingers' contacts but hangs free counts as held).
bool off_the_table(const PhysicsWorld& world, int id) {
  for (int other : world.touching(id, 0.0))
    if (world.has(other) && world.role(other) == BodyRole::kFixture) return false;
  return true;
}

// "the hand stopped 23 mm short of the pose (finger +y: 025_mug); " or "".
std::string approach_text(const GraspAttempt& r) {
  if (r.reached_pose) return "";
  std::string text = "the hand stopped " + millimetres(r.pose_error_m) + " short of the pose";
  if (!r.stopped_by.empty()) text += " (" + joined(r.stopped_by) + ")";
  return text + "; ";
}

// Closes the fingers until they hold an object (it touches both, within `tolerance_m`) and
// stall there - the aperture changes less than `stall_m` over `stall_window_s` - until they
// are fully closed, or until `max_close_s` passes. A finger pushing an object across the
// table, or turning it against the other finger, is still closing.
void close_fingers(PhysicsWorld& world, Gripper& gripper, const AttemptOptions& options,
                   double tolerance_m) {
  const double dt = world.options().time_step_s;
  const int window = std::max(1, int(std::ceil(options.stall_window_s / dt)));
  const int max_windows = std::max(1, int(std::ceil(options.max_close_s / (window * dt))));
  const double closed_m = options.gripper.geometry.min_aperture_m + options.stall_m;
  gripper.drive_fingers(-options.gripper.finger_speed_m_s);
  double before = gripper.aperture_m();
  for (int i = 0; i < max_windows; ++i) {
    world.step(window);
    const double now = gripper.aperture_m();
    const bool stalled = std::abs(before - now) < options.stall_m;
    if (now <= closed_m || (stalled && !gripper.pinched(tolerance_m).empty())) return;
    before = now;
  }
}

// Closes, lifts and judges; fills the closing and lifting part of the record.
int close_and_lift(PhysicsWorld& world, Gripper& gripper, const AttemptOptions& options,
                   GraspAttempt& r) {
  const double tolerance = 0.002;
  close_fingers(world, gripper, options, tolerance);
  r.opening_at_contact_m = gripper.aperture_m();
  r.touching_at_closing = part_names(world, gripper.touching_parts(tolerance));
  r.surface_at_closing_m = surface_near_hand(world, options.gripper.geometry, r.X_BaseHand_closing);
  const std::set<int> pinched = gripper.pinched(tolerance);
  if (pinched.empty()) {
    r.outcome = GraspOutcome::kEmptyGrasp;
    r.reason =
        approach_text(r) + "the fingers closed on nothing (" +
        (r.between_fingers_at_detection.empty()
             ? std::string("no object was between the planned fingers")
             : "planned around " + joined(r.between_fingers_at_detection)) +
        (r.touching_at_closing.empty() ? "" : "; touching " + joined(r.touching_at_closing)) + ")";
    return -1;
  }
  r.pinched_object = world.name(*pinched.begin());
  const std::map<int, Rise> rise = lift_and_hold(world, gripper, options, pinched);
  const std::set<int> still_pinched = gripper.pinched(tolerance);
  int held = -1;
  for (const auto& [id, metres] : rise) {
    r.lift_m = std::max(r.lift_m, metres.highest_m);
    if (held < 0 && still_pinched.count(id) && off_the_table(world, id)) held = id;
  }
  if (held >= 0) {
    r.outcome = GraspOutcome::kSuccess;
    r.reason = approach_text(r) + "held " + world.name(held) + " at " +
               millimetres(r.opening_at_contact_m) + " opening";
  } else {
    r.outcome = GraspOutcome::kSlipped;
    r.reason = approach_text(r) + r.pinched_object + " pinched at " +
               millimetres(r.opening_at_contact_m) + " opening slipped after rising " +
               millimetres(r.lift_m);
  }
  return held;
}

}  // namespace

AttemptResult attempt_grasp(PhysicsWorld& world, const Eigen::Isometry3d& X_BaseHand,
                            const AttemptOptions& options) {
  AttemptResult result;
  GraspAttempt& r = result.record;
  const HandBody body = make_hand_body(options.gripper.geometry);
  const double start_s = world.time_s();
  r.X_BaseHand_planned = X_BaseHand;
  r.between_fingers_at_detection = objects_between_fingers(world, body, X_BaseHand);
  r.in_collision_at_planned_pose = gripper_overlaps(world, body, X_BaseHand);
  {
    const Eigen::Vector3d back = -options.standoff_m * X_BaseHand.linear().col(0);
    Gripper gripper(world, options.gripper, shifted(X_BaseHand, back));
    const auto at_standoff = gripper.touching_parts();
    r.X_BaseHand_closing = gripper.actual_pose();
    if (!at_standoff.empty()) {
      r.outcome = GraspOutcome::kCollisionOnApproach;
      r.stopped_by = part_names(world, at_standoff);
      r.reason = "at the stand-off pose the gripper touches " + joined(r.stopped_by);
    } else {
      approach(world, gripper, X_BaseHand, options, r);
      r.X_BaseHand_closing = gripper.actual_pose();
      r.pose_error_m = distance_m(r.X_BaseHand_closing, X_BaseHand);
      r.reached_pose = r.pose_error_m <= options.pose_tolerance_m;
      // Resting against what stopped it, the gripper's contacts are within a hair of zero.
      if (!r.reached_pose) r.stopped_by = part_names(world, gripper.touching_parts(0.001));
      r.between_fingers_at_closing = objects_between_fingers(world, body, r.X_BaseHand_closing);
      result.held_object = close_and_lift(world, gripper, options, r);
    }
  }
  r.duration_s = world.time_s() - start_s;
  return result;
}

}  // namespace antipode::cells
