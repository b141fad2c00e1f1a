#pragma once
// The collision checks' settings as component parameters: `collision` (spheres_then_exact,
// exact or spheres: arm_collision_world.hpp's CheckMode), `sphere_overshoot_m` and
// `points_octree` (per_leaf or point_by_point), shared by the plugins that build an
// ArmCollisionWorld (the OMPL planner, the cluster selector).

#include "antipode/core/parameters.hpp"
#include "arm_collision_world.hpp"

namespace antipode::collision {

/// "spheres_then_exact", "exact" or "spheres".
const char* to_string(CheckMode mode);

/// The options `params` give (`default_mode` and the other defaults where absent). Fails
/// through `params` (a located error naming the choices) for an unknown mode or octree build,
/// or an overshoot outside [0.001, 0.1] m.
CollisionOptions collision_options(const Parameters& params,
                                   CheckMode default_mode = CheckMode::kSpheresThenExact);

}  // namespace antipode::collision
