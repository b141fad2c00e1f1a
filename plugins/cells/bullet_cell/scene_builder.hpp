#pragma once
// Builds a scene's table, box and objects into a physics world, deterministically from a seed.

#include <cstdint>
#include <map>
#include <string>

#include "physics_world.hpp"
#include "scene_spec.hpp"

namespace antipode::cells {

/// Listings of mesh folders, kept across resets.
class MeshCache {
 public:
  const std::vector<std::string>& names(const std::string& folder);

 private:
  std::map<std::string, std::vector<std::string>> listings_;
};

/// Adds the table (and box) then places the scene's objects by its placement rule and lets
/// them settle. Objects that fell off the table are removed. Returns the object ids.
std::vector<int> build_scene(const SceneSpec& spec, std::uint64_t seed, MeshCache& meshes,
                             PhysicsWorld& world);

/// The models a scene places for `seed`, in placement order (listed objects first).
std::vector<ObjectModel> scene_objects(const SceneSpec& spec, std::uint64_t seed,
                                       MeshCache& meshes);

}  // namespace antipode::cells
