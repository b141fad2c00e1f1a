// The fingers of a robot's URDF against its gripper file. The algorithm:
//  1. The fingers are the links below `gripper_from` whose parent joint is prismatic.
//  2. Each finger's shapes are sampled (box corners, cylinder rims, sphere poles) in the
//     grasp frame - x the approach, y the closing direction - with the finger's joint at its
//     lower and at its upper limit (the rest of the hand is rigid: its pose does not matter).
//  3. The finger on +y closes with its lowest y, the one on -y with its highest: their gap is
//     the aperture, closed at the lower limits and open at the upper ones.
//  4. The fingers' farthest point along the approach is how far they reach beyond the palm
//     face; their extent along y and z is their thickness and height.
#include <algorithm>
#include <cmath>
#include <limits>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_model.hpp"
#include "robot_check.hpp"

namespace antipode::collision {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Points on the surface of `shape` that bound it along every axis, in the link's frame.
std::vector<Eigen::Vector3d> outline(const CollisionPrimitive& shape) {
  std::vector<Eigen::Vector3d> local;
  const Eigen::Vector3d s = shape.size_m;
  switch (shape.kind) {
    case CollisionPrimitive::Kind::kBox:
      for (int i = 0; i < 8; ++i)
        local.emplace_back((i & 1 ? 0.5 : -0.5) * s.x(), (i & 2 ? 0.5 : -0.5) * s.y(),
                           (i & 4 ? 0.5 : -0.5) * s.z());
      break;
    case CollisionPrimitive::Kind::kCylinder:
      for (int k = 0; k < 32; ++k) {
        const double a = 2.0 * kPi * k / 32.0;
        for (double z : {-0.5 * s.y(), 0.5 * s.y()})
          local.emplace_back(s.x() * std::cos(a), s.x() * std::sin(a), z);
      }
      break;
    case CollisionPrimitive::Kind::kSphere:
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
          Eigen::Vector3d p = Eigen::Vector3d::Zero();
          p[axis] = sign * s.x();
          local.push_back(p);
        }
      break;
  }
  for (Eigen::Vector3d& p : local) p = shape.X_LinkShape * p;
  return local;
}

struct Finger {
  std::string link;
  KinematicChain from_hand;  // gripper_from -> finger, one prismatic joint
  std::vector<Eigen::Vector3d> points_link;
};

std::vector<Finger> fingers_of(const RobotModel& robot, const std::string& hand) {
  std::vector<Finger> fingers;
  for (const std::string& link : robot.link_names()) {
    std::string joint;
    bool moving = false;
    robot.parent_link(link, &joint, &moving);
    if (!moving || link == hand) continue;
    bool below = false;  // is `hand` an ancestor?
    for (std::string up = robot.parent_link(link); !up.empty(); up = robot.parent_link(up))
      below = below || up == hand;
    if (!below) continue;
    KinematicChain chain = robot.chain(hand, link);
    if (chain.dof() != 1) continue;
    Finger finger{link, chain, {}};
    for (const CollisionPrimitive& shape : robot.collision_shapes(link))
      for (const Eigen::Vector3d& p : outline(shape)) finger.points_link.push_back(p);
    if (!finger.points_link.empty()) fingers.push_back(std::move(finger));
  }
  return fingers;
}

// A finger's points in the grasp frame with its joint at `q`.
std::vector<Eigen::Vector3d> in_grasp(const Finger& finger, const Eigen::Isometry3d& X_GraspHand,
                                      double q) {
  Eigen::VectorXd joint(1);
  joint[0] = q;
  const Eigen::Isometry3d X = X_GraspHand * finger.from_hand.forward(joint);
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : finger.points_link) points.push_back(X * p);
  return points;
}

double mean_y(const std::vector<Eigen::Vector3d>& points) {
  double sum = 0.0;
  for (const auto& p : points) sum += p.y();
  return sum / double(points.size());
}

// The gap between the fingers' closing faces with every finger at its lower (or upper) limit.
double aperture(const std::vector<Finger>& fingers, const Eigen::Isometry3d& X_GraspHand,
                bool open) {
  double plus_face = std::numeric_limits<double>::infinity();
  double minus_face = -std::numeric_limits<double>::infinity();
  for (const Finger& finger : fingers) {
    const JointLimits& limits = finger.from_hand.limits().front();
    const auto points = in_grasp(finger, X_GraspHand, open ? limits.upper : limits.lower);
    for (const auto& p : points) {
      if (mean_y(points) > 0.0)
        plus_face = std::min(plus_face, p.y());
      else
        minus_face = std::max(minus_face, p.y());
    }
  }
  return plus_face - minus_face;
}

GripperMatch match(const char* quantity, double urdf_m, double file_m, bool at_least,
                   double tolerance_m) {
  GripperMatch m{quantity, urdf_m, file_m, true, true};
  m.ok =
      at_least ? urdf_m >= file_m - tolerance_m : std::abs(urdf_m - file_m) <= tolerance_m + 1e-9;
  return m;
}

}  // namespace

std::vector<GripperMatch> match_gripper(const RobotFile& robot_file, double tolerance_m) {
  const RobotModel robot = RobotModel::load(robot_file.urdf_path);
  const std::vector<Finger> fingers = fingers_of(robot, robot_file.gripper_from);
  if (fingers.size() != 2) {
    throw Error(robot_file.path + ": " + std::to_string(fingers.size()) +
                " fingers (links with collision shapes behind a prismatic joint) below '" +
                robot_file.gripper_from + "'; a parallel gripper has 2");
  }
  const Eigen::Isometry3d X_GraspHand = robot.chain(robot_file.gripper_from, robot_file.arm_tip)
                                            .forward(Eigen::VectorXd(0))
                                            .inverse();
  const HandGeometry& hand = robot_file.gripper;
  std::vector<GripperMatch> matches = {
      match("closed aperture", aperture(fingers, X_GraspHand, false), hand.min_aperture_m, false,
            tolerance_m),
      match("open aperture", aperture(fingers, X_GraspHand, true), hand.max_aperture_m, false,
            tolerance_m)};
  // Reach along the approach, thickness along y, height along z: the first finger, open.
  double reach = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  const Finger& first = fingers.front();
  for (const auto& p : in_grasp(first, X_GraspHand, first.from_hand.limits().front().upper)) {
    reach = std::max(reach, p.x());
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const Finger& finger : fingers)
    for (const auto& p : in_grasp(finger, X_GraspHand, finger.from_hand.limits().front().upper))
      reach = std::max(reach, p.x());
  matches.push_back(match("finger reach beyond the palm face (at least the depth)", reach,
                          hand.depth_m, true, tolerance_m));
  GripperMatch thickness =
      match("finger thickness", hi.y() - lo.y(), hand.finger_width_m, false, tolerance_m);
  GripperMatch height = match("finger height", hi.z() - lo.z(), hand.height_m, false, tolerance_m);
  thickness.required = height.required = false;  // the sampler's fingers may be idealised
  matches.push_back(thickness);
  matches.push_back(height);
  return matches;
}

}  // namespace antipode::collision
