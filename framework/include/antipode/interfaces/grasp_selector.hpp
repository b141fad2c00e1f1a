#pragma once
/// @file
/// GraspSelector: chooses and ranks the grasps to try from classified hands (paper
/// section 5.1), keeping the reason for every hand it drops.

#include "antipode/core/stop_token.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

class GraspSelector : public Component {
 public:
  ComponentKind kind() const final { return ComponentKind::kGraspSelector; }

  /// The selection from `hands` (typically a classifier's output, in any frame).
  ///
  /// Contract: the result has `hands`' cloud, geometry and support. Its hand list starts with
  /// the grasps worth trying, best first, each with rejection kNone (a grasp may be a new
  /// hand, such as the mean of a cluster); every other hand of the input follows in input
  /// order with the reason it was not chosen (its earlier rejection, or the selector's:
  /// kBelowSupport, kApertureLimit, kClustered with `merged_into` naming its grasp, ...).
  /// No grasp at the front means none was found (not an error). Hands with a rejection or
  /// a label other than kPositive or kUnknown are never chosen. Deterministic; may be called
  /// concurrently. Throws antipode::Error only for unusable input (a set without a cloud),
  /// and Cancelled when `stop` asks to stop.
  virtual HandSet select(const HandSet& hands, const StopToken& stop) const = 0;
};

}  // namespace antipode
