#pragma once
// The final approach of a grasp: the hand moves in a straight line from the pre-grasp to the
// grasp along its approach direction. Solved as a chain of inverse kinematics problems, one
// every `step_m`, each seeded with the previous solution, so that the arm's joints change
// continuously; every state is checked in the arm's collision world.
//
// Frames and units: X_BaseHand in the robot's base frame; metres and radians.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "antipode/robot/kinematic_chain.hpp"
#include "arm_collision_world.hpp"

namespace antipode::planning {

struct ApproachOptions {
  double step_m = 0.01;              ///< hand travel between solved states
  double max_joint_step_rad = 0.15;  ///< a larger change between two states is a jump
};

/// The joint states from `q_pregrasp` (the hand `distance_m` back along the approach of
/// X_BaseHand) to the grasp, first and last included, or none when a step has no IK
/// solution near the one before it, jumps, or collides.
std::optional<std::vector<Eigen::VectorXd>> straight_approach(
    const KinematicChain& arm, const collision::ArmCollisionWorld& world,
    const Eigen::Isometry3d& X_BaseHand, double distance_m, const Eigen::VectorXd& q_pregrasp,
    const ApproachOptions& options = {});

}  // namespace antipode::planning
