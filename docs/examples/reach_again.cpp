// Forward and inverse kinematics of Baxter's right arm (docs/robot.md, "Chains"), compiled
// by the tests.
#include <Eigen/Geometry>

#include "antipode/robot/inverse_kinematics.hpp"
#include "antipode/robot/robot_model.hpp"

// The joint angles the IK solver finds for the hand pose that `q_rad` reaches, or an empty
// vector when it finds none.
Eigen::VectorXd reach_again(const Eigen::VectorXd& q_rad) {
  const antipode::RobotModel robot = antipode::RobotModel::load("robots/baxter/baxter.urdf");
  const antipode::KinematicChain arm = robot.chain("base", "right_gripper");  // 7 joints
  const Eigen::Isometry3d X_BaseHand = arm.forward(q_rad);                    // metres, radians
  const antipode::IkResult ik = antipode::solve_ik(arm, X_BaseHand, arm.mid_range());
  if (ik.status == antipode::IkStatus::kSolved) return ik.solutions.front();
  return {};
}
