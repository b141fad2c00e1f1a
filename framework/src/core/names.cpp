// String names of the core enums, used in messages, traces and JSON output.
#include "antipode/core/hand.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"
#include "antipode/interfaces/motion_planner.hpp"

namespace antipode {

const char* to_string(HandLabel label) {
  switch (label) {
    case HandLabel::kUnknown:
      return "unknown";
    case HandLabel::kPositive:
      return "positive";
    case HandLabel::kNegative:
      return "negative";
    case HandLabel::kIndeterminate:
      return "indeterminate";
  }
  return "?";
}

const char* to_string(Rejection reason) {
  switch (reason) {
    case Rejection::kNone:
      return "none";
    case Rejection::kInCollision:
      return "in collision";
    case Rejection::kEmptyClosingRegion:
      return "empty closing region";
    case Rejection::kTooWide:
      return "too wide for the gripper";
    case Rejection::kNotAntipodal:
      return "not antipodal";
    case Rejection::kLowScore:
      return "low score";
    case Rejection::kNoIk:
      return "no inverse kinematics solution";
    case Rejection::kNoPlan:
      return "no motion plan";
    case Rejection::kOutOfWorkspace:
      return "out of workspace";
    case Rejection::kBelowSupport:
      return "below the support";
    case Rejection::kApertureLimit:
      return "at the aperture limits";
    case Rejection::kClustered:
      return "clustered into another grasp";
    case Rejection::kSmallCluster:
      return "cluster too small";
    case Rejection::kNotSelected:
      return "not selected";
    case Rejection::kUnbalanced:
      return "too far from the centre of mass";
    case Rejection::kNoIkAtPreGrasp:
      return "no inverse kinematics solution at the pre-grasp";
    case Rejection::kOtherObject:
      return "not on the chosen object";
    case Rejection::kFingersOverAnEdge:
      return "fingers over an edge";
    case Rejection::kWidestBeyondTheTips:
      return "widest beyond the fingertips";
    case Rejection::kPluginReason:
      return "a plugin's reason";
  }
  return "?";
}

const char* to_string(ComponentKind kind) {
  switch (kind) {
    case ComponentKind::kSampler:
      return "sampler";
    case ComponentKind::kClassifier:
      return "classifier";
    case ComponentKind::kGraspSelector:
      return "selector";
    case ComponentKind::kMotionPlanner:
      return "planner";
    case ComponentKind::kCell:
      return "cell";
  }
  return "?";
}

const char* to_string(GraspOutcome outcome) {
  switch (outcome) {
    case GraspOutcome::kSuccess:
      return "success";
    case GraspOutcome::kArmCollision:
      return "collision with the environment";
    case GraspOutcome::kCollisionOnApproach:
      return "collision on approach";
    case GraspOutcome::kEmptyGrasp:
      return "empty grasp";
    case GraspOutcome::kSlipped:
      return "slipped";
    case GraspOutcome::kObjectKnockedOut:
      return "object knocked out";
    case GraspOutcome::kNotExecuted:
      return "not executed";
  }
  return "?";
}

const char* to_string(PlanningStatus status) {
  switch (status) {
    case PlanningStatus::kSolved:
      return "solved";
    case PlanningStatus::kStartInCollision:
      return "start in collision";
    case PlanningStatus::kStartInvalid:
      return "invalid start";
    case PlanningStatus::kNoIkAtGrasp:
      return "no IK at the grasp";
    case PlanningStatus::kNoIkAtPreGrasp:
      return "no IK at the pre-grasp";
    case PlanningStatus::kNoApproach:
      return "no straight approach";
    case PlanningStatus::kGoalInCollision:
      return "goal in collision";
    case PlanningStatus::kTimedOut:
      return "timed out";
    case PlanningStatus::kCancelled:
      return "cancelled";
  }
  return "?";
}

}  // namespace antipode
