#pragma once
// Depth views by ray casting triangle meshes with Embree 3, turned into base-frame points.

#include <cstdint>
#include <memory>
#include <vector>

#include "antipode/core/cloud.hpp"
#include "antipode/core/random.hpp"
#include "camera.hpp"
#include "physics_world.hpp"
#include "sensor_model.hpp"

namespace antipode::cells {

/// One Embree device, reused for every view; one renderer per cell.
class DepthRenderer {
 public:
  DepthRenderer();
  ~DepthRenderer();
  DepthRenderer(const DepthRenderer&) = delete;
  DepthRenderer& operator=(const DepthRenderer&) = delete;

  /// Loads the meshes at their poses; later render() calls see this scene.
  void set_scene(const std::vector<PhysicsWorld::Visual>& visuals);

  /// The points `camera` sees, in the base frame, with `sensor`'s noise drawn from `random`.
  /// Every point gets view mask bit `view_index`; the camera position is appended to
  /// `cloud.view_origins_m` by the caller. `threads` workers share the rows; the result does
  /// not depend on their number.
  void render(const CameraSpec& camera, const SensorModel& sensor, const RandomStream& random,
              std::uint32_t view_index, Cloud& cloud, int threads = 1) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace antipode::cells
