#pragma once
// Quick tests between two primitive shapes (robot_model.hpp's boxes, cylinders and spheres),
// asked before FCL where the fast path's spheres flag a pair (arm_collision_world.hpp, spheres
// then FCL). Most flagged pairs are in fact apart by millimetres to centimetres - the spheres
// reach up to 3 cm past Baxter's 6 cm cylinders' flat ends - and a separating plane shows it
// sooner than FCL's general (GJK) test: for a cylinder and a box, 0.17 us against 0.28 us with
// FCL for the 3.5% left undecided (collision_bench --benchmark_filter=ConfirmPair); a sphere
// against anything costs a distance.
//
// How, by kinds:
// - a sphere with anything: the distance from its centre to the other shape, exact;
// - two boxes: the separating axis test (Gottschalk, Lin and Manocha 1996: the boxes are apart
//   if and only if their projections onto one of 15 axes are), exact;
// - a cylinder with a box or a cylinder: apart when the gap along a candidate axis is positive
//   (each shape's reach along the axis is exact, so a positive gap is a separating plane); the
//   axes are each shape's own, their cross products, the line between the centres, and the line
//   between the nearest points (the box's point nearest the cylinder's axis, or the two axes'
//   nearest points). Meeting when a point found lies inside both (that point of the box, or one
//   between the two axes), or when inscribed boxes (the square of side R sqrt(2), two per
//   cylinder turned 45 degrees) meet. Otherwise the test cannot tell.
// An answer is given only with kMargin_m to spare - shapes closer than that to touching, or
// overlapping by less, are left to FCL - so where this test answers, FCL answers the same.
//
// Frames and units: both shapes placed in one frame (X_FrameA, X_FrameB: each shape's centre,
// and for a cylinder its axis along z, as FCL places them); metres. Threads: pure functions.

#include <Eigen/Geometry>

#include "antipode/robot/robot_model.hpp"

namespace antipode::collision {

enum class Verdict { kApart, kMeet, kUndecided };

/// A primitive's kind and sizes (CollisionPrimitive's size_m convention; its X_LinkShape is
/// not read) placed at X_FrameShape.
struct PlacedPrimitive {
  CollisionPrimitive::Kind kind = CollisionPrimitive::Kind::kBox;
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
  Eigen::Isometry3d X_FrameShape = Eigen::Isometry3d::Identity();
};

/// Shapes closer than this to touching, or overlapping by less, are undecided (m).
constexpr double kMargin_m = 1e-5;

/// Whether a and b are apart, meet, or cannot be told apart by these tests.
Verdict quick_test(const PlacedPrimitive& a, const PlacedPrimitive& b);

}  // namespace antipode::collision
