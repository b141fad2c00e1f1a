#pragma once
/// @file
/// Classifier: scores and labels hand hypotheses (paper section 4).

#include <string>

#include "antipode/core/hand_geometry.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

class Classifier : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kClassifier; }

  /// Sets `score` and `label` of every hand in `hands`; hands judged not to be grasps get
  /// label kNegative and a rejection reason. Never reorders or removes hands. Scores are
  /// unitless (larger: more likely a grasp); the hands keep their frame. Deterministic, and
  /// may be called concurrently on different hand sets (the shipped classifiers keep no
  /// state between calls). Throws antipode::Error only for unusable input (hands whose
  /// cloud is missing), and Cancelled when `stop` asks to stop (the hands' scores are then
  /// unspecified).
  virtual void classify(HandSet& hands, const StopToken& stop) const = 0;

  /// Why this classifier cannot score hands of the gripper `hand` (a model trained for
  /// another gripper describes another closing region), as one sentence that says how to get
  /// one that can; empty when it can. A tree that loads a sampler whose hand() a classifier
  /// refuses is a load error naming both components. Const and thread-safe.
  virtual std::string hand_problem(const HandGeometry& hand) const {
    (void)hand;
    return {};
  }
};

}  // namespace antipode
