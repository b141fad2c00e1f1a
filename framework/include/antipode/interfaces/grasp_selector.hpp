#pragma once
/// @file
/// GraspSelector: chooses and ranks the grasps to try from classified hands (paper
/// section 5.1), keeping the reason for every hand it drops; and screens out, before
/// classification, the hands it would drop whatever their score.

#include "antipode/core/cloud.hpp"
#include "antipode/core/stop_token.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/interfaces/component.hpp"
#include "antipode/interfaces/hand_set.hpp"

namespace antipode {

/// Where a selection's time went, for benchmarks and diagnostics: a selector adds what it
/// measures and leaves the rest at zero. Seconds of wall time on the calling thread.
struct SelectionTimes {
  /// The arm's reach checks (inverse kinematics and collision checks at the grasps and
  /// their pre-grasps), the building of their collision world included.
  double reach_s = 0.0;
};

/// What a selector may know besides the hands. Everything is optional: a selector for a
/// free-floating hand needs none of it.
struct SelectionContext {
  /// The observed points a robot arm must avoid, in the robot's base frame (the whole
  /// capture, which reaches beyond the sampler's workspace); null: the hands' cloud.
  CloudPtr scene;
  /// The arm's joint state now (Cell::arm_state()), from which its reach is judged; empty:
  /// the selector's own choice.
  JointState start;
  StopToken stop;  ///< cancellation
  /// Where the selector adds its times; null: none are kept. Not shared between concurrent
  /// selections.
  SelectionTimes* times = nullptr;
};

/// Whether a selector may choose `hand`: no rejection, labelled positive or not yet labelled
/// (a sampler's output).
inline bool selectable(const Hand& hand) {
  return hand.rejection == Rejection::kNone &&
         (hand.label == HandLabel::kPositive || hand.label == HandLabel::kUnknown);
}

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
  /// and Cancelled when `context.stop` asks to stop.
  virtual HandSet select(const HandSet& hands, const SelectionContext& context) const = 0;

  /// The hands this selector would drop whatever a classifier made of them - judged by the
  /// geometry alone (the support, the box's walls, the aperture, ...) - marked with their
  /// reasons, so that a classifier need not describe them (the node `ScreenHands` before
  /// `ClassifyHands`, which classifies only the hands without a rejection).
  ///
  /// Contract: the result is `hands` with the same hands in the same order, unchanged but for
  /// the rejection of some hands that had none. What `select` then chooses from the
  /// screened hands, classified, is what it chooses from all of them, classified: a screen
  /// only saves work. The default screens out nothing. Deterministic; may be called
  /// concurrently. Throws antipode::Error only for unusable input (a set without a cloud),
  /// and Cancelled when `context.stop` asks to stop.
  virtual HandSet screen(const HandSet& hands, const SelectionContext& context) const {
    (void)context;
    return hands;
  }
};

}  // namespace antipode
