#pragma once
// The bullet_cell component: a simulated table-top cell (Bullet physics, Embree depth views).

#include <memory>
#include <optional>

#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/cell.hpp"
#include "cell_arm.hpp"
#include "depth_renderer.hpp"
#include "execution_noise.hpp"
#include "grasp_attempt.hpp"
#include "scene_builder.hpp"

namespace antipode::cells {

struct CellOptions {
  PhysicsOptions physics;
  AttemptOptions attempt;
  ExecutionNoise execution;  ///< the error of each executed hand pose (none by default)
  SensorModel sensor;
  std::uint64_t seed = 0;
  int render_threads = 2;             ///< threads sharing a view's rows (same cloud for any number)
  std::optional<CellArmOptions> arm;  ///< the robot arm; none: a free-floating hand
};

/// Reads the cell's parameters (docs/cell.md); throws antipode::Error located in the file.
CellOptions read_cell_options(const Parameters& params, const SceneSpec& scene);

class BulletCell final : public Cell {
 public:
  /// From tree parameters: `scene` (a scene file) and the options of docs/cell.md.
  explicit BulletCell(const Parameters& params);
  BulletCell(SceneSpec scene, const CellOptions& options);

  /// Checks `params` as the first constructor does - the scene file, the options, the arm's
  /// robot file and home pose - without building the world. Throws antipode::Error.
  static void check_parameters(const Parameters& params);

  std::vector<std::string> view_names() const override;
  Cloud capture(const std::vector<std::string>& views) override;
  JointState arm_state() const override;
  /// The objects in the workspace: on the table and, in a scene that keeps its box, inside
  /// the box's walls (an object on the table beside the box has left the workspace).
  std::optional<int> objects_left() const override { return int(objects_in_workspace().size()); }
  /// Each object in the workspace: its name, pose and narrowest horizontal extent (from its
  /// rendered mesh).
  std::vector<ObjectTruth> object_truth() const override;
  /// The objects the scene's recipe placed at the last reset (its count, after any refills).
  std::optional<int> objects_placed() const override { return placed_; }
  GraspAttempt execute(const GraspRequest& request) override;
  void reset(std::uint64_t seed) override;
  /// The objects' recipes, poses and motion, the fixtures and the clock (PhysicsSnapshot).
  std::shared_ptr<const CellState> save() const override;
  /// Rebuilds the world from a state this cell saved (a fresh Bullet world: every restore of
  /// one state steps identically); the captures and attempts counted go back too.
  void restore(const CellState& state) override;

  /// Ground truth, for tests and tools.
  const PhysicsWorld& world() const { return *world_; }
  std::vector<int> objects() const { return world_->ids(BodyRole::kObject); }
  /// The objects objects_left() counts.
  std::vector<int> objects_in_workspace() const;
  const SceneSpec& scene() const { return scene_; }
  int attempts() const { return attempts_; }

 private:
  /// Removes the objects below the table top.
  void remove_fallen_objects();
  /// The names of the objects of `before` (all but `held`, the object picked) that have
  /// left the workspace since, each with where it went.
  std::vector<std::string> names_gone(const std::vector<int>& before, int held) const;
  /// Follows the request's trajectory with the arm: "" when it reached the grasp without
  /// touching the scene, else the refusal (outcome kNotExecuted) or contact (kArmCollision).
  std::string follow_trajectory(const GraspRequest& request, GraspOutcome* outcome) const;

  SceneSpec scene_;
  CellOptions options_;
  MeshCache meshes_;
  std::unique_ptr<PhysicsWorld> world_;
  std::shared_ptr<const CellArm> arm_;
  DepthRenderer renderer_;
  std::uint64_t seed_ = 0;
  int captures_ = 0;
  int attempts_ = 0;
  int placed_ = 0;  ///< objects the last reset placed
};

}  // namespace antipode::cells
