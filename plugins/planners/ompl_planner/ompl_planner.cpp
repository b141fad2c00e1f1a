#include "ompl_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "antipode/core/error.hpp"
#include "antipode/robot/robot_file.hpp"
#include "arm_planner.hpp"
#include "collision_options.hpp"
#include "collision_pairs.hpp"
#include "reach_check.hpp"

namespace antipode::planning {
namespace {

using Clock = std::chrono::steady_clock;

OmplPlannerOptions read_options(const Parameters& p) {
  OmplPlannerOptions o;
  const RobotFile robot = robot_file_parameter(p, "robot");
  o.robot_file = robot.urdf_path;
  o.arm_tip = robot.arm_tip;
  o.points_unchecked = robot.points_unchecked;
  o.points_resolution_m = p.get<double>("points_resolution_m", o.points_resolution_m);
  o.collision = collision::collision_options(p);
  o.planner = p.get<std::string>("planner", o.planner);
  o.time_limit_s = p.get<double>("time_limit_s", o.time_limit_s);
  o.resolution_rad = p.get<double>("resolution_rad", o.resolution_rad);
  o.range_rad = p.get<double>("range_rad", o.range_rad);
  o.late_range_rad = p.get<double>("late_range_rad", o.late_range_rad);
  o.late_after_states = p.get<long>("late_after_states", o.late_after_states);
  const std::string order = p.get<std::string>("segment_order", "rake");
  if (order != "rake" && order != "in_order")
    p.fail("segment_order", "'segment_order' must be rake or in_order, got '" + order + "'");
  o.rake_segments = order == "rake";
  o.ik_solutions = p.get<int>("ik_solutions", o.ik_solutions);
  o.speed_fraction = p.get<double>("speed_fraction", o.speed_fraction);
  o.approach.step_m = p.get<double>("approach_step_m", o.approach.step_m);
  const auto positive = [&p](const char* key, double value) {
    if (!(value > 0.0)) p.fail(key, std::string("'") + key + "' must be positive");
  };
  positive("points_resolution_m", o.points_resolution_m);
  positive("time_limit_s", o.time_limit_s);
  positive("resolution_rad", o.resolution_rad);
  if (!(o.range_rad >= 0.0 && std::isfinite(o.range_rad)))
    p.fail("range_rad", "'range_rad' must be finite and not negative (0: OMPL's)");
  if (o.range_rad > 0.0 && o.planner == "PRM")
    p.fail("range_rad", "'range_rad' is for RRTConnect, RRT, KPIECE1 and EST, not PRM");
  if (!(o.late_range_rad >= 0.0 && std::isfinite(o.late_range_rad)))
    p.fail("late_range_rad",
           "'late_range_rad' must be finite and not negative (0: keep range_rad)");
  if (o.late_after_states < 0)
    p.fail("late_after_states", "'late_after_states' must not be negative");
  positive("ik_solutions", o.ik_solutions);
  positive("approach_step_m", o.approach.step_m);
  if (!(o.speed_fraction > 0.0 && o.speed_fraction <= 1.0))
    p.fail("speed_fraction", "'speed_fraction' must be in (0, 1]");
  p.reject_unknown();
  return o;
}

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

PlanningStatus reach_failure(collision::ReachStatus status) {
  switch (status) {
    case collision::ReachStatus::kNoIkAtGrasp:
      return PlanningStatus::kNoIkAtGrasp;
    case collision::ReachStatus::kNoIkAtPreGrasp:
      return PlanningStatus::kNoIkAtPreGrasp;
    default:
      return PlanningStatus::kGoalInCollision;
  }
}

// Waypoints with times: each segment at `speed_fraction` of its slowest joint's velocity
// limit.
Trajectory timed_trajectory(const KinematicChain& arm, const std::vector<Eigen::VectorXd>& q,
                            double speed_fraction) {
  Trajectory t;
  t.joint_names = arm.joint_names();
  double time_s = 0.0;
  for (std::size_t w = 0; w < q.size(); ++w) {
    for (std::size_t j = 0; w > 0 && j < arm.dof(); ++j) {
      const double speed = std::max(1e-3, arm.limits()[j].velocity * speed_fraction);
      const auto i = Eigen::Index(j);
      time_s = std::max(time_s, t.times_s.back() + std::abs(q[w][i] - q[w - 1][i]) / speed);
    }
    t.positions_rad.push_back(joint_values(q[w]));
    t.times_s.push_back(time_s);
  }
  return t;
}

}  // namespace

OmplPlanner::OmplPlanner(const Parameters& params) : OmplPlanner(read_options(params)) {}

void OmplPlanner::check_parameters(const Parameters& params) { (void)read_options(params); }

OmplPlanner::OmplPlanner(const OmplPlannerOptions& options)
    : options_(options),
      robot_(RobotModel::load(options.robot_file)),
      arm_(robot_.chain(robot_.root_link(), options.arm_tip)),
      gripper_links_(collision::shaped_links_below(robot_, options.points_unchecked)) {}

std::shared_ptr<const collision::ArmCollisionWorld> OmplPlanner::world_for(
    const CloudPtr& scene) const {
  const std::lock_guard<std::mutex> lock(cache_mutex_);
  if (!cached_world_ || scene != cached_scene_) {
    auto world = std::make_shared<collision::ArmCollisionWorld>(
        robot_, arm_, std::map<std::string, double>{}, options_.collision);
    if (scene) world->set_points(scene->points_m, options_.points_resolution_m, gripper_links_);
    cached_scene_ = scene;  // held, so that its address is not reused while cached
    cached_world_ = std::move(world);
  }
  return cached_world_;
}

std::shared_ptr<const collision::ArmCollisionWorld> OmplPlanner::world_with_obstacles(
    const PlanningProblem& problem) const {
  auto world = std::make_shared<collision::ArmCollisionWorld>(
      robot_, arm_, std::map<std::string, double>{}, options_.collision);
  for (const Obstacle& o : problem.obstacles) {
    if (o.shape == Obstacle::Shape::kBox)
      world->add_box(o.name, o.X_BaseObstacle, o.size_m);
    else
      world->add_cylinder(o.name, o.X_BaseObstacle, o.size_m.x(), o.size_m.y());
  }
  if (problem.scene)
    world->set_points(problem.scene->points_m, options_.points_resolution_m, gripper_links_);
  return world;
}

std::vector<Eigen::VectorXd> OmplPlanner::find_goal(const collision::ArmCollisionWorld& world,
                                                    const Eigen::VectorXd& start,
                                                    const PlanningProblem& problem,
                                                    PlanningResult& result) const {
  collision::ReachOptions reach_options;
  reach_options.pregrasp_m = problem.standoff_m;
  reach_options.grasp_solutions = options_.ik_solutions;
  result.status = PlanningStatus::kNoIkAtGrasp;
  for (const Eigen::Isometry3d& X :
       {problem.grasp.X_FrameHand, collision::half_turned(problem.grasp.X_FrameHand)}) {
    if (problem.stop.stop_requested()) break;
    const collision::Reach reach = collision::check_reach(arm_, world, X, start, reach_options);
    if (reach.status != collision::ReachStatus::kReachable) {
      if (result.status == PlanningStatus::kNoIkAtGrasp) {
        result.status = reach_failure(reach.status);
        result.detail = reach.detail;
      }
      continue;
    }
    if (auto states = straight_approach(arm_, world, X, problem.standoff_m, reach.q_pregrasp,
                                        options_.approach)) {
      result.X_BaseHand = X;
      return std::move(*states);
    }
    result.status = PlanningStatus::kNoApproach;
  }
  if (problem.stop.stop_requested()) result.status = PlanningStatus::kCancelled;
  return {};
}

PlanningResult OmplPlanner::plan(const PlanningProblem& problem) const {
  if (problem.grasp.frame != robot_.root_link())
    throw Error("ompl_planner: the grasp is in frame '" + problem.grasp.frame +
                "', the robot's base is '" + robot_.root_link() + "'");
  PlanningResult result;
  const Clock::time_point t0 = Clock::now();
  if (problem.start.names != arm_.joint_names() ||
      problem.start.positions_rad.size() != arm_.dof()) {
    result.status = PlanningStatus::kStartInvalid;
    result.detail = "the start state does not name the arm's joints in order";
    return result;
  }
  const Eigen::VectorXd start = joint_vector(problem.start.positions_rad);
  const std::shared_ptr<const collision::ArmCollisionWorld> shared_world =
      problem.obstacles.empty() ? world_for(problem.scene) : world_with_obstacles(problem);
  const collision::ArmCollisionWorld& world = *shared_world;
  if (const collision::ContactReport contact = world.check(start); !contact.free()) {
    result.status = PlanningStatus::kStartInCollision;
    result.detail = contact.str();
    return result;
  }
  // The goal (pre-grasp ... grasp), then the path from the start to its first state.
  const std::vector<Eigen::VectorXd> approach = find_goal(world, start, problem, result);
  result.goal_s = seconds_since(t0);
  if (approach.empty()) return result;

  ArmPlanningProblem search;
  search.arm = &arm_;
  search.world = &world;
  search.start = start;
  search.goal = approach.front();
  search.planner = options_.planner;
  search.time_limit_s = problem.time_limit_s > 0.0 ? problem.time_limit_s : options_.time_limit_s;
  search.resolution_rad = options_.resolution_rad;
  search.range_rad = options_.range_rad;
  search.late_range_rad = options_.late_range_rad;
  search.late_after_states = options_.late_after_states;
  search.rake_segments = options_.rake_segments;
  search.seed = problem.seed;
  search.stop = problem.stop;
  const ArmPlan path = plan_arm_motion(search);
  result.search_s = path.planning_s;
  result.collision_checks = path.collision_checks;
  result.simplify_s = path.shortening_s;
  if (path.status != PlanStatus::kSolved) {
    result.status = path.status == PlanStatus::kCancelled ? PlanningStatus::kCancelled
                                                          : PlanningStatus::kTimedOut;
    result.detail = to_string(path.status);
    return result;
  }
  std::vector<Eigen::VectorXd> waypoints = path.path;
  waypoints.insert(waypoints.end(), approach.begin() + 1, approach.end());
  result.trajectory = timed_trajectory(arm_, waypoints, options_.speed_fraction);
  result.status = PlanningStatus::kSolved;
  return result;
}

}  // namespace antipode::planning
