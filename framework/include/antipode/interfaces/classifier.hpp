#pragma once
/// @file
/// Classifier: scores and labels hand hypotheses (paper section 4).

#include "antipode/core/stop_token.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

class Classifier : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kClassifier; }

  /// Sets `score` and `label` of every hand in `hands`; hands judged not to be grasps get
  /// label kNegative and a rejection reason. Never reorders or removes hands. Throws
  /// Cancelled when `stop` asks to stop (the hands' scores are then unspecified).
  virtual void classify(HandSet& hands, const StopToken& stop) const = 0;
};

}  // namespace antipode
