#pragma once
// The ompl_planner component (MotionPlanner): plans Baxter's (or any URDF arm's) motion to a
// grasp - collision-free IK at the grasp and the pre-grasp (reach_check.hpp), an OMPL path
// from the start state to the pre-grasp (arm_planner.hpp), then the straight approach
// (straight_approach.hpp). See docs/robot.md#the-ompl_planner-plugin for the parameters.
//
// Threads: plan() is const; concurrent calls are safe. The collision world of the last scene
// planned in (the robot and the scene's octree) is kept, under a mutex, for the next call on
// the same scene: a selection's grasps are planned in one capture.

#include <memory>
#include <mutex>
#include <string>

#include "antipode/core/parameters.hpp"
#include "antipode/interfaces/motion_planner.hpp"
#include "antipode/robot/robot_model.hpp"
#include "arm_collision_world.hpp"
#include "straight_approach.hpp"

namespace antipode::planning {

struct OmplPlannerOptions {
  std::string robot_file;
  std::string arm_tip;                        ///< the grasp frame (RobotFile::arm_tip)
  std::vector<std::string> points_unchecked;  ///< RobotFile::points_unchecked
  double points_resolution_m = 0.01;
  collision::CollisionOptions collision;  ///< how the arm's states are checked
  std::string planner = "RRTConnect";
  double time_limit_s = 1.0;
  double resolution_rad = 0.02;
  double range_rad = 0.0;          ///< the search's longest motion (ArmPlanningProblem); 0: OMPL's
  double late_range_rad = 1.0;     ///< the longest motion of a long search (ArmPlanningProblem)
  long late_after_states = 20000;  ///< states checked before a search is long
  bool rake_segments = true;       ///< segment_order: rake (true) or in_order
  int ik_solutions = 12;
  double speed_fraction = 0.5;  ///< of each joint's velocity limit, for the waypoint times
  ApproachOptions approach;
};

class OmplPlanner final : public MotionPlanner {
 public:
  explicit OmplPlanner(const Parameters& params);
  explicit OmplPlanner(const OmplPlannerOptions& options);

  /// Checks `params` as the first constructor does (the robot file, its tip and links
  /// included) without building the planner. Throws antipode::Error.
  static void check_parameters(const Parameters& params);

  PlanningResult plan(const PlanningProblem& problem) const override;

  const KinematicChain& arm() const { return arm_; }

 private:
  /// The robot and `scene`'s points (none: the robot alone), built once per scene.
  std::shared_ptr<const collision::ArmCollisionWorld> world_for(const CloudPtr& scene) const;
  /// The robot, the problem's points and its obstacles, built for it alone.
  std::shared_ptr<const collision::ArmCollisionWorld> world_with_obstacles(
      const PlanningProblem& problem) const;

  /// The states of the straight approach, pre-grasp first, for the grasp as given or
  /// half-turned; empty, with result.status and result.detail saying why, when neither has one.
  std::vector<Eigen::VectorXd> find_goal(const collision::ArmCollisionWorld& world,
                                         const Eigen::VectorXd& start,
                                         const PlanningProblem& problem,
                                         PlanningResult& result) const;

  OmplPlannerOptions options_;
  RobotModel robot_;
  KinematicChain arm_;
  std::vector<std::string> gripper_links_;
  mutable std::mutex cache_mutex_;
  mutable CloudPtr cached_scene_;
  mutable std::shared_ptr<const collision::ArmCollisionWorld> cached_world_;
};

}  // namespace antipode::planning
