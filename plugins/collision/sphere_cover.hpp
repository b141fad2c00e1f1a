#pragma once
// Spheres that cover a primitive shape: every point of the shape lies in at least one sphere,
// and no sphere reaches farther than `overshoot_m` beyond the shape. The fast collision path
// (sphere_arm.hpp) checks these spheres instead of the shapes, so it never calls a contact
// free; the overshoot is what it may call a contact where there is none.
//
// How: a sphere of radius r whose centre lies d inside the shape reaches at most r - d beyond
// it (the shape holds the ball of radius d about the centre), which is each sphere's
// overshoot bound. A box is cut into a grid of n_x * n_y * n_z sub-boxes, each held by the
// sphere through its corners; the grid chosen is the one with the fewest sub-boxes whose
// worst bound is within the target or, when none is, within half the target of the least
// bound any grid reaches. A cylinder gets spheres on its axis, one per slab of its length
// (sphere_cover.cpp: a flat end costs (sqrt(2) - 1) times the radius, 2.5 cm for a 6 cm
// radius, whatever the target). A sphere is itself.
//
// Each sphere also says how deep its centre lies in the shape (`inner_m`): the ball of that
// radius about the centre lies inside the shape. Where that ball meets an obstacle, the shape
// does too, so a check may call such a contact certain without testing the shape itself.
//
// Frames and units: spheres in the frame of the primitive's link (the primitive's
// X_LinkShape applied), metres.

#include <vector>

#include <Eigen/Core>

#include "antipode/robot/robot_model.hpp"

namespace antipode::collision {

struct Sphere {
  Eigen::Vector3d center_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
  double inner_m = 0.0;  ///< the ball of this radius about the centre lies inside the shape
};

struct SphereCover {
  std::vector<Sphere> spheres;
  double overshoot_m = 0.0;  ///< the worst sphere's bound (0 for a sphere primitive)
};

/// The cover of `shape` for an overshoot of at most `max_overshoot_m` where its kind of cover
/// can keep to it (the result's overshoot_m says what it reaches), a box's grid having at most
/// `max_spheres` cells. Throws antipode::Error for a non-positive overshoot or sphere budget,
/// or a shape with a non-positive size.
SphereCover cover_with_spheres(const CollisionPrimitive& shape, double max_overshoot_m,
                               int max_spheres = 64);

}  // namespace antipode::collision
