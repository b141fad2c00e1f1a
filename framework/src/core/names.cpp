// String names of the core enums, used in messages, traces and JSON output.
#include "antipode/core/hand.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/grasp_attempt.hpp"

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

}  // namespace antipode
