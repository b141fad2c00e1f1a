#pragma once
// Planning problems from scene files of known solids (scenes/planning/*.yaml): the
// MotionBenchMaker scenes (table pick, box, cage, three bookshelves), their variations
// sampled by seed, and a query per problem - the hand in front of (or above) a target object -
// placed for a robot (docs/robot.md, Planning benchmarks).
//
// Frames and units: a scene file gives its objects in a frame of the robot (`robots: NAME:
// frame`) moved by an offset; problems are in the robot's base frame. Metres, radians.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "antipode/interfaces/motion_planner.hpp"

namespace antipode::evaluation {

/// One object of a planning scene: a box or a cylinder (Obstacle's sizes) at its nominal
/// pose in the scene's frame.
struct SceneSolid {
  Obstacle solid;  ///< X_BaseObstacle holds the nominal pose in the scene's frame
  Eigen::Vector3d position_sigma_m = Eigen::Vector3d::Zero();  ///< the variation
  Eigen::Vector3d rotation_bound_rad = Eigen::Vector3d::Zero();
};

struct PlanningScene {
  std::string path;
  std::vector<SceneSolid> objects;
  Eigen::Vector3d world_sigma_m = Eigen::Vector3d::Zero();  ///< moves every object
  Eigen::Vector3d world_bound_rad = Eigen::Vector3d::Zero();
  std::vector<std::string> targets;
  bool approach_down = false;  ///< down along the target's -z, else along its x
  double standoff_m = 0.12;
  /// Where the scene stands for a robot (named by its robot file's stem, e.g. "panda").
  struct Placement {
    std::string robot;
    std::string frame;
    Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();
    double standoff_m = 0.12;  ///< the scene's, unless the robot's hand asks for another
  };
  std::vector<Placement> robots;
};

/// Reads a planning scene file. Throws antipode::Error naming the file, the key's line and
/// the fix for a missing or unknown key, a shape other than box_m or cylinder, a size that is
/// not positive, a quaternion of zero length, or a target that names no object.
PlanningScene read_planning_scene(const std::string& path);

/// One problem: the scene's solids for the robot and the goal pose of its hand.
struct PlanningQuery {
  std::vector<Obstacle> obstacles;  ///< base frame
  std::string target;
  Eigen::Isometry3d X_BaseHand = Eigen::Isometry3d::Identity();  ///< the goal (standoff 0)
};

/// The problem of `seed`: the variations drawn from a stream of that seed (MotionBenchMaker's
/// sampler: each position normal with the stated standard deviation, each rotation uniform
/// within its bounds about x, then y, then z; the world's moves every object about the frame's
/// origin, an object's moves it about its own centre), the target targets[seed % count], the
/// scene placed at X_BaseFrame * offset. Throws antipode::Error for a robot the scene does not
/// place.
PlanningQuery sample_planning_query(const PlanningScene& scene, const std::string& robot,
                                    const Eigen::Isometry3d& X_BaseFrame, std::uint64_t seed);

/// The frame a scene places `robot` in (its `robots` entry). Throws like sample_planning_query.
const std::string& planning_frame(const PlanningScene& scene, const std::string& robot);

}  // namespace antipode::evaluation
