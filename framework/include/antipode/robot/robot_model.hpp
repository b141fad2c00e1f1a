#pragma once
/// @file
/// A robot read from a URDF file (urdfdom): its links, joints and limits, and the serial
/// chains between any two links for kinematics (KinematicChain). The collision shapes of
/// the file are kept by the robot's collision world, not here.
///
/// Threads: a model is immutable once loaded; its const members may be called
/// concurrently. Copies share the parsed description.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"

namespace antipode {

/// One primitive collision shape of a link (URDF <collision>), in the link's frame.
struct CollisionPrimitive {
  enum class Kind { kBox, kCylinder, kSphere };
  Kind kind = Kind::kBox;
  Eigen::Isometry3d X_LinkShape = Eigen::Isometry3d::Identity();  ///< centre; cylinders along z
  /// Box: the lengths along x, y, z. Cylinder: radius, length, 0. Sphere: radius, 0, 0. (m)
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
};

class RobotModel {
 public:
  /// Reads a URDF file. Throws antipode::Error naming the file when it is missing or
  /// unreadable, is not valid URDF (urdfdom's reason), or has no link.
  static RobotModel load(const std::string& path);
  /// Parses URDF text; `source` names it in errors (a file name, or e.g. "<string>").
  static RobotModel parse(const std::string& urdf_xml, const std::string& source);

  const std::string& name() const;    ///< the <robot name=...>
  const std::string& source() const;  ///< the file (or source) it was read from
  const std::string& root_link() const;
  std::vector<std::string> link_names() const;   ///< sorted
  std::vector<std::string> joint_names() const;  ///< sorted, fixed joints included
  bool has_link(const std::string& name) const;
  /// The parent of `link` ("" for the root); `joint` receives the joint between them and
  /// `moving` whether it moves (not fixed). Throws antipode::Error for an unknown link.
  std::string parent_link(const std::string& link, std::string* joint = nullptr,
                          bool* moving = nullptr) const;
  /// The link's collision shapes. Throws antipode::Error for an unknown link and for a
  /// mesh shape (antipode's robot descriptions use primitives only).
  std::vector<CollisionPrimitive> collision_shapes(const std::string& link) const;

  /// The chain from `base` to `tip`, where `base` is an ancestor of `tip` (or the same
  /// link: an empty chain). Throws antipode::Error for an unknown link (suggesting the
  /// nearest name), a `tip` not below `base`, or a joint on the way of a kind the
  /// kinematics does not handle (floating, planar).
  KinematicChain chain(const std::string& base, const std::string& tip) const;

  struct Impl;

 private:
  explicit RobotModel(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

}  // namespace antipode
