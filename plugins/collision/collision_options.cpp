#include "collision_options.hpp"

#include <string>

#include "antipode/core/error.hpp"

namespace antipode::collision {

const char* to_string(CheckMode mode) {
  switch (mode) {
    case CheckMode::kSpheresThenExact:
      return "spheres_then_exact";
    case CheckMode::kExact:
      return "exact";
    case CheckMode::kSpheres:
      return "spheres";
  }
  return "?";
}

CollisionOptions collision_options(const Parameters& params, CheckMode default_mode) {
  CollisionOptions o;
  o.mode = default_mode;
  const std::string mode = params.get<std::string>("collision", to_string(o.mode));
  bool known = false;
  for (const CheckMode m : {CheckMode::kSpheresThenExact, CheckMode::kExact, CheckMode::kSpheres})
    if (mode == to_string(m)) {
      o.mode = m;
      known = true;
    }
  if (!known)
    params.fail("collision",
                "'collision' must be spheres_then_exact, exact or spheres, got '" + mode + "'");
  o.sphere_overshoot_m = params.number_in("sphere_overshoot_m", o.sphere_overshoot_m, 0.001, 0.1);
  const std::string octree = params.get<std::string>("points_octree", "per_leaf");
  if (octree != "per_leaf" && octree != "point_by_point")
    params.fail("points_octree", "'points_octree' must be per_leaf or point_by_point, got '" +
                                     octree + "'" +
                                     did_you_mean(octree, {"per_leaf", "point_by_point"}));
  o.octree_point_by_point = octree == "point_by_point";
  return o;
}

}  // namespace antipode::collision
